#pragma once
// A yarn that reflects and transmits: its Ashikhmin-Shirley lobe in its local frame and the
// point's YarnTransmission in a frame of its own (the front face's yarn, MODEL_TRANSMISSION.md
// section 3), sampled by one-sample MIS between the two (section 2). The reflection's frame
// parts the directions: wo and wi on one side of it reflect, on opposite sides they transmit,
// and there the cosine factor is taken about the transmission frame's normal (cosineNormal()).
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
    bool choosesLobe() const { return true; }  // sample() reads uc
    bool transmits() const { return true; }
    // The thread's colour as its reflection shows it: what the albedo render pass keeps.
    glm::vec3 albedo() const { return reflection_.albedo(); }

    const AshikhminShirley& reflection() const { return reflection_; }
    const YarnTransmission& transmission() const { return transmission_; }
    const Frame& transmissionFrame() const { return transmissionFrame_; }
    // The normal of the cosine factor for wo and wi: z where they reflect, the transmission
    // frame's normal where they cross, which is the same from either face, so that light and
    // camera subpaths weight the point alike (bsdf.h's cosineNormal()).
    glm::vec3 cosineNormal(const glm::vec3& wo, const glm::vec3& wi) const {
        return wo.z * wi.z > 0.0f ? glm::vec3(0, 0, 1) : transmissionFrame_.z;
    }
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
