#pragma once
// WovenParams to and from the JSON object used by scene files and `woven bsdf-eval`.
#include <nlohmann/json.hpp>

#include "woven_params.h"

namespace woven {

// Fields absent from `j` keep their value in `base`, except those with a fallback in
// wovenParamTable() (warp_ex <- ex, ...), which follow their fallback when it is given.
// Throws std::invalid_argument naming the field: unknown keys, wrong types, values out of range.
WovenParams paramsFromJson(const nlohmann::json& j, const WovenParams& base = {});
nlohmann::json paramsToJson(const WovenParams& p);

}  // namespace woven
