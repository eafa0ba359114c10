#pragma once
// The light a yarn passes to the other side of the cloth (docs/MODEL_TRANSMISSION.md): a diffuse
// part and a glossy forward part, the Ashikhmin-Shirley specular lobe mirrored through the sheet,
// in the yarn's local frame (z = the normal of the face seen). Non-zero only where wo and wi lie
// on opposite sides; reciprocal, and bounded so that with the yarn's reflection R + T <= 1.
#include <glm/glm.hpp>
#include <optional>

#include "ashikhmin_shirley.h"

namespace woven {

// The body transmittance T of a yarn of diffuse colour rd that passes a fraction t of the light
// it does not reflect: t (1 - rd) (rd / max(rd))^2, the dye's hue deepened (MODEL_TRANSMISSION.md 1).
glm::vec3 yarnTransmittance(const glm::vec3& rd, float t);

class YarnTransmission {
public:
    // shape: the yarn's lobe (its exponents and R_s); transmittance: T; gloss: g, the forward share.
    YarnTransmission(const LobeShape& shape, const glm::vec3& transmittance, float gloss)
        : specular_(shape, glm::vec3(0.0f), 1.0f), transmittance_(transmittance), gloss_(gloss) {}

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    bool transmits() const { return true; }

    const glm::vec3& transmittance() const { return transmittance_; }
    float gloss() const { return gloss_; }

private:
    AshikhminShirley specular_;  // its half-vector density and sampler; no diffuse term
    glm::vec3 transmittance_;
    float gloss_;
};

}  // namespace woven
