#include "fit_output.h"

#include <cmath>
#include <stdexcept>

#include "uv_scale.h"
#include "woven_params_json.h"

namespace woven {

std::optional<glm::dvec2> threadsPerCm(const Shot& shot, const glm::vec2& repeat) {
    try {
        const glm::dvec2 metres = measureUvScale(*shot.scene, shot.meshes).metresPerUv;
        if (!(metres.x > 0.0 && metres.y > 0.0)) return std::nullopt;
        return glm::dvec2(repeat) / (100.0 * metres);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

nlohmann::json fittedMaterialJson(const WovenParams& params, const Shot& shot) {
    nlohmann::json j = paramsToJson(params);
    if (const auto counts = threadsPerCm(shot, params.repeat)) {
        j.erase("repeat");
        // Three figures after the point: a thread count to 0.1 % is beyond any photo's precision.
        j["ends_per_cm"] = std::round(counts->x * 1000.0) / 1000.0;
        j["picks_per_cm"] = std::round(counts->y * 1000.0) / 1000.0;
    }
    return j;
}

}  // namespace woven
