#pragma once
// A yarn that reflects and transmits: its Ashikhmin-Shirley lobe in its local frame and the
// point's YarnTransmission in a frame of its own (the front face's yarn, MODEL_TRANSMISSION.md
// section 3), sampled by one-sample MIS between the two (section 2). Each part is zero where the
// other one lives (reflection above its frame, transmission across its own), so the BSDF is
// their sum.
#include "surface_bsdf.h"
#include "yarn_transmission.h"

namespace woven {

class TransmittingYarn {
public:
    // `transmissionFrame`: the transmission's frame in the reflection's local coordinates.
    TransmittingYarn(const AshikhminShirley& reflection, const YarnTransmission& transmission,
                     const Frame& transmissionFrame = Frame{});

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    bool transmits() const { return true; }
    // The thread's colour as its reflection shows it: what the albedo render pass keeps.
    glm::vec3 albedo() const { return reflection_.albedo(); }

    const AshikhminShirley& reflection() const { return reflection_; }
    const YarnTransmission& transmission() const { return transmission_; }
    const Frame& transmissionFrame() const { return transmissionFrame_; }
    float transmissionProbability() const { return transmitProb_; }

private:
    AshikhminShirley reflection_;
    YarnTransmission transmission_;
    Frame transmissionFrame_;
    float transmitProb_;
};

// The two framed lobes of a point (WovenShading's bsdf and transmission) as one, in the
// reflection's frame.
FramedLobe<TransmittingYarn> transmittingYarn(const SurfaceBsdf& reflection, const FramedLobe<YarnTransmission>& transmission);

}  // namespace woven
