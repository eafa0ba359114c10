#pragma once
// `woven bsdf-eval`'s answer to one line of its input: a JSON query
//   {"material": {...}, "uv": [u, v], "wi": [x, y, z], "wo": [x, y, z]}
// in, {"f": [r, g, b], "pdf": p, "yarn": "weft|warp|gap|far"} out ("far": a uv too large for a
// double to place within a quarter thread, answered toward the weave's far field, one warning a
// run). The lines come from anyone's program, so each is bounded (length, JSON depth) and every
// problem is an exception with a message, never a crash.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "woven_params.h"

namespace woven {

// The woven parameters of a material as bsdf-eval and bsdf-plot read it: materialFromJson's keys
// (presets, thread counts, a draft), on the flat surface whose UV unit is a metre. Warnings go
// to stderr; throws std::invalid_argument naming the key.
WovenParams flatSurfaceParams(const nlohmann::json& material);

// Longer lines are refused unread: a query with a material is well under a kilobyte.
constexpr size_t kMaxBsdfEvalLineBytes = size_t(1) << 20;

class BsdfEval {
public:
    BsdfEval();
    ~BsdfEval();

    // The answer's JSON text; throws std::exception whose message says what is wrong with the
    // query. Materials are built once and kept for the lines that follow.
    std::string answer(std::string_view line);

private:
    class MaterialCache;
    std::unique_ptr<MaterialCache> materials_;
    bool warnedFarUv_ = false;
};

}  // namespace woven
