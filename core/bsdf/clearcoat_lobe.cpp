#include "clearcoat_lobe.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
constexpr float kCoatF0 = 0.04f;  // IOR 1.5
float coatFresnel(float cosTheta) { return kCoatF0 + (1.0f - kCoatF0) * schlickWeight(cosTheta); }
}  // namespace

ClearcoatLobe::ClearcoatLobe(float weight, float roughness, const glm::vec3& normal)
    : weight_(std::clamp(std::isfinite(weight) ? weight : 0.0f, 0.0f, 1.0f)),
      ggx_(roughness * roughness),
      frame_(Frame::fromNormal(normal)) {}

glm::vec3 ClearcoatLobe::eval(const glm::vec3& woBase, const glm::vec3& wiBase) const {
    const glm::vec3 wo = frame_.toLocal(woBase), wi = frame_.toLocal(wiBase);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 H = wo + wi;
    const float len = glm::length(H);
    if (!(len > 1e-12f)) return glm::vec3(0.0f);
    const glm::vec3 h = H / len;
    // wo.h as |wo + wi| / 2, symmetric in the two directions: reciprocal to the last bit.
    return glm::vec3(weight_ * coatFresnel(0.5f * len) * ggx_.D(h) * ggx_.visibility(wo, wi));
}

float ClearcoatLobe::pdf(const glm::vec3& woBase, const glm::vec3& wiBase) const {
    const glm::vec3 wi = frame_.toLocal(wiBase);
    // sample() rejects the reflections below the coat's horizon: they have no density. With a
    // tilted coat normal some of them are above the base's horizon, where GltfBxdf asks.
    if (wi.z <= 0.0f) return 0.0f;
    return ggx_.reflectionPdf(frame_.toLocal(woBase), wi);
}

std::optional<glm::vec3> ClearcoatLobe::sample(const glm::vec3& woBase, const glm::vec2& u) const {
    const glm::vec3 wo = frame_.toLocal(woBase);
    if (wo.z <= 0.0f) return std::nullopt;
    const glm::vec3 h = ggx_.sampleVisibleNormal(wo, u);
    const glm::vec3 wi = 2.0f * glm::dot(wo, h) * h - wo;
    if (wi.z <= 0.0f) return std::nullopt;
    return frame_.toWorld(wi);
}

float ClearcoatLobe::baseScale(const glm::vec3& wo, const glm::vec3& wi) const {
    if (!active()) return 1.0f;
    const float cosO = std::abs(glm::dot(wo, frame_.z)), cosI = std::abs(glm::dot(wi, frame_.z));
    return 1.0f - weight_ * std::max(coatFresnel(cosO), coatFresnel(cosI));
}

float ClearcoatLobe::reflectance(const glm::vec3& wo) const {
    return active() ? weight_ * coatFresnel(std::max(glm::dot(wo, frame_.z), 0.0f)) : 0.0f;
}

}  // namespace woven
