#pragma once
// What `woven fit` writes (docs/FIT.md): the fitted woven material as JSON with the names used
// everywhere (woven_params_json.h), ready for a scene file's "materials"; where the target
// mesh's size is known (its UVs measure it, uv_scale.h) its thread counts as ends and picks per
// cm instead of `repeat`, so that it puts the swatch's cloth on any mesh.
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <optional>

#include "fabric_fit.h"
#include "shot.h"

namespace woven {

// Ends and picks per cm of `repeat` on the shot's target; nullopt where its UVs do not measure it.
std::optional<glm::dvec2> threadsPerCm(const Shot& shot, const glm::vec2& repeat);

nlohmann::json fittedMaterialJson(const WovenParams& params, const Shot& shot);

}  // namespace woven
