#include "transmitting_yarn.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
float mean(const glm::vec3& c) { return (c.r + c.g + c.b) / 3.0f; }

// By the share of the energy each part carries at normal incidence, clamped so that neither
// density vanishes where its part does not.
float chooseTransmission(const AshikhminShirley& r, const YarnTransmission& t) {
    const float rs = r.shape().rs;
    const float reflected = rs + (1.0f - rs) * mean(r.rd()), transmitted = (1.0f - rs) * mean(t.transmittance());
    if (!(reflected + transmitted > 0.0f)) return 0.5f;
    return std::clamp(transmitted / (reflected + transmitted), 0.05f, 0.95f);
}
}  // namespace

TransmittingYarn::TransmittingYarn(const AshikhminShirley& reflection, const YarnTransmission& transmission,
                                   const Frame& transmissionFrame)
    : reflection_(reflection),
      transmission_(transmission),
      transmissionFrame_(transmissionFrame),
      transmitProb_(chooseTransmission(reflection, transmission)) {}

glm::vec3 TransmittingYarn::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    const Frame& t = transmissionFrame_;
    return wo.z * wi.z > 0.0f ? reflection_.eval(wo, wi) : transmission_.eval(t.toLocal(wo), t.toLocal(wi));
}

float TransmittingYarn::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    const Frame& t = transmissionFrame_;
    return wo.z * wi.z > 0.0f ? (1.0f - transmitProb_) * reflection_.pdf(wo, wi)
                              : transmitProb_ * transmission_.pdf(t.toLocal(wo), t.toLocal(wi));
}

std::optional<BsdfSample> TransmittingYarn::sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
    // uc chooses the part and, rescaled to [0, 1), that part's own lobe.
    const bool transmit = uc < transmitProb_;
    std::optional<BsdfSample> s;
    if (transmit) {
        s = transmission_.sample(transmissionFrame_.toLocal(wo), u, uc / transmitProb_);
        if (s) s->wi = transmissionFrame_.toWorld(s->wi);
    } else {
        s = reflection_.sample(wo, u, std::min((uc - transmitProb_) / (1.0f - transmitProb_), 0x1.fffffep-1f));
    }
    // A part's sample on the other part's side is dropped, so the density is pdf()'s (the two
    // frames tilt apart where the faces' bumps differ).
    if (!s || (wo.z * s->wi.z > 0.0f) == transmit) return std::nullopt;
    s->pdf = pdf(wo, s->wi);
    if (!(s->pdf > 0.0f) || !std::isfinite(s->pdf)) return std::nullopt;
    s->f = eval(wo, s->wi);
    s->weight = s->f * (std::fabs(glm::dot(s->wi, cosineNormal(wo, s->wi))) / s->pdf);
    return s;
}

FramedLobe<TransmittingYarn> transmittingYarn(const SurfaceBsdf& reflection, const FramedLobe<YarnTransmission>& transmission) {
    const Frame& r = reflection.frame();
    const Frame& t = transmission.frame();
    const Frame relative{r.toLocal(t.x), r.toLocal(t.y), r.toLocal(t.z)};
    return FramedLobe<TransmittingYarn>(r, TransmittingYarn(reflection.lobe(), transmission.lobe(), relative));
}

}  // namespace woven
