#pragma once
// The BSDF at one shading point in world space: a reflection lobe in its shading frame. Every
// material reduces to this at a hit: the woven material per yarn point, the standard fallback
// with an isotropic exponent.
#include "ashikhmin_shirley.h"
#include "frame.h"

namespace woven {

class SurfaceBsdf {
public:
    SurfaceBsdf(const Frame& frame, const AshikhminShirley& lobe) : frame_(frame), lobe_(lobe) {}

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
    const Frame& frame() const { return frame_; }
    const glm::vec3& shadingNormal() const { return frame_.z; }
    const AshikhminShirley& lobe() const { return lobe_; }

private:
    Frame frame_;
    AshikhminShirley lobe_;
};

}  // namespace woven
