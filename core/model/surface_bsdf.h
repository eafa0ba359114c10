#pragma once
// A lobe in its shading frame, seen in world space: directions go to the lobe's local frame
// (z = the shading normal) and samples come back. Every BSDF at a hit is one: the woven model's
// Ashikhmin-Shirley lobe per yarn point (SurfaceBsdf), and the renderer's Bsdf over every kind
// of lobe (core/bsdf/bsdf.h).
#include <optional>
#include <utility>

#include "ashikhmin_shirley.h"
#include "frame.h"

namespace woven {

template <class Lobe>
class FramedLobe {
public:
    FramedLobe(const Frame& frame, const Lobe& lobe) : frame_(frame), lobe_(lobe) {}
    // The lobe built in place from its constructor's arguments, not copied in: the renderer
    // builds a BSDF at every path vertex.
    template <class... Args>
    FramedLobe(const Frame& frame, std::in_place_t, Args&&... args) : frame_(frame), lobe_(std::forward<Args>(args)...) {}

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const {
        return lobe_.eval(frame_.toLocal(wo), frame_.toLocal(wi));
    }
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        return lobe_.pdf(frame_.toLocal(wo), frame_.toLocal(wi));
    }
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
        auto s = lobe_.sample(frame_.toLocal(wo), u, uc);
        if (s) s->wi = frame_.toWorld(s->wi);
        return s;
    }
    // Whether sample() reads its uc: an integrator draws that number only then.
    bool choosesLobe() const { return lobe_.choosesLobe(); }
    // Whether light may pass to the other side of the surface (else the lobe only reflects).
    bool transmits() const { return lobe_.transmits(); }
    // The reflectance the albedo render pass shows (sample_contributions.h's FirstHit).
    glm::vec3 albedo() const { return lobe_.albedo(); }
    const Frame& frame() const { return frame_; }
    const glm::vec3& shadingNormal() const { return frame_.z; }
    const Lobe& lobe() const { return lobe_; }

private:
    Frame frame_;
    Lobe lobe_;
};

// The woven model's BSDF at one yarn point.
using SurfaceBsdf = FramedLobe<AshikhminShirley>;

}  // namespace woven
