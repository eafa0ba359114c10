#pragma once
// One query of `woven bsdf-eval`: a JSON object naming a woven material, uv, wi and wo, answered
// by the BSDF's value, pdf and top yarn as a JSON object. Apart from the command so that the
// command and its fuzz target (fuzz/fuzz_bsdf_eval.cpp) run the same code.
#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>

#include "woven_material.h"

namespace woven {

// Materials are rebuilt only when a line's material differs from every one seen before.
class MaterialCache {
public:
    // Throws std::invalid_argument naming the key, DraftError for a draft it names.
    const WovenMaterial& get(const nlohmann::json& j);

private:
    std::map<std::string, std::unique_ptr<WovenMaterial>> cache_;
};

// {"f":[r,g,b],"pdf":p,"yarn":"weft|warp|gap"} for one parsed input line. Throws
// std::invalid_argument (or DraftError) saying what is wrong with the query.
nlohmann::json evalLine(MaterialCache& cache, const nlohmann::json& query);

}  // namespace woven
