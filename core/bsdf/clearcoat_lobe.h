#pragma once
// KHR_materials_clearcoat's layer: a GGX dielectric coat of IOR 1.5 (F0 = 0.04) with its own
// roughness and normal, over the rest of the material. Local frame of the base, z = the base's
// normal; the coat's normal is given in that frame. The layer below is scaled by
// 1 - weight F(n_c . w) for the stronger of the two directions, which keeps the BSDF reciprocal
// (the extension's reference scales by the view direction alone).
#include <optional>

#include "bsdf_sample.h"
#include "frame.h"
#include "ggx.h"

namespace woven {

class ClearcoatLobe {
public:
    // No coat (active() is false), for nothing: GltfBxdf builds one for every surface.
    ClearcoatLobe() = default;
    ClearcoatLobe(float weight, float roughness, const glm::vec3& normal);

    bool active() const { return weight_ > 0.0f; }
    float weight() const { return weight_; }
    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<glm::vec3> sample(const glm::vec3& wo, const glm::vec2& u) const;
    // What the layer below sees of a pair of directions.
    float baseScale(const glm::vec3& wo, const glm::vec3& wi) const;
    // The coat's reflectance towards wo at normal incidence on its normal, for choosing lobes.
    float reflectance(const glm::vec3& wo) const;

private:
    float weight_ = 0.0f;
    TrowbridgeReitz ggx_{1.0f};
    Frame frame_;  // z = the coat's normal, in the base's frame
};

}  // namespace woven
