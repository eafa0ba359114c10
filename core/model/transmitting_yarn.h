#pragma once
// A yarn that reflects and transmits: its Ashikhmin-Shirley lobe and its YarnTransmission in one
// local frame, sampled by one-sample MIS between the two (docs/MODEL_TRANSMISSION.md section 2).
#include "yarn_transmission.h"

namespace woven {

class TransmittingYarn {
public:
    TransmittingYarn(const AshikhminShirley& reflection, const YarnTransmission& transmission);

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    bool transmits() const { return true; }
    // The thread's colour as its reflection shows it: what the albedo render pass keeps.
    glm::vec3 albedo() const { return reflection_.albedo(); }

    const AshikhminShirley& reflection() const { return reflection_; }
    const YarnTransmission& transmission() const { return transmission_; }
    float transmissionProbability() const { return transmitProb_; }

private:
    AshikhminShirley reflection_;
    YarnTransmission transmission_;
    float transmitProb_;
};

}  // namespace woven
