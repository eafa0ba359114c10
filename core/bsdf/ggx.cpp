#include "ggx.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"

namespace woven {

float TrowbridgeReitz::D(const glm::vec3& h) const {
    if (h.z <= 0.0f) return 0.0f;
    // 1 / (pi ax ay (x^2 / ax^2 + y^2 / ay^2 + z^2)^2) written as KHR_materials_anisotropy's
    // reference does, which is, isotropic, a^2 / (pi (a^2 cos^2 + sin^2)^2): no cancellation near
    // h = n, where a small alpha puts all of D.
    const float a2 = alphaX_ * alphaY_;
    const glm::vec3 f(alphaY_ * h.x, alphaX_ * h.y, a2 * h.z);
    const float w2 = a2 / glm::dot(f, f);
    return a2 * w2 * w2 / kPi;
}

float TrowbridgeReitz::stretchedLength(const glm::vec3& w) const {
    return std::sqrt(alphaX_ * alphaX_ * w.x * w.x + alphaY_ * alphaY_ * w.y * w.y + w.z * w.z);
}

float TrowbridgeReitz::lambda(const glm::vec3& w) const {
    const float cos = std::abs(w.z);
    if (!(cos > 0.0f)) return std::numeric_limits<float>::infinity();
    return 0.5f * (stretchedLength(w) / cos - 1.0f);
}

float TrowbridgeReitz::visibility(const glm::vec3& wo, const glm::vec3& wi) const {
    const float no = std::abs(wo.z), ni = std::abs(wi.z);
    if (!(no > 0.0f) || !(ni > 0.0f)) return 0.0f;
    return 0.5f / (ni * stretchedLength(wo) + no * stretchedLength(wi));
}

glm::vec3 TrowbridgeReitz::sampleVisibleNormal(const glm::vec3& w, const glm::vec2& u) const {
    // Heitz 2018: stretch to the unit-roughness configuration, sample the projected disk of the
    // visible hemisphere, unstretch.
    const glm::vec3 wh = glm::normalize(glm::vec3(alphaX_ * w.x, alphaY_ * w.y, w.z));
    const float len2 = wh.x * wh.x + wh.y * wh.y;
    const glm::vec3 t1 = len2 > 0.0f ? glm::vec3(-wh.y, wh.x, 0.0f) / std::sqrt(len2) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(wh, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + wh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * wh;
    return glm::normalize(glm::vec3(alphaX_ * nh.x, alphaY_ * nh.y, std::max(1e-6f, nh.z)));
}

float TrowbridgeReitz::visibleNormalPdf(const glm::vec3& w, const glm::vec3& h) const {
    if (!(w.z > 0.0f)) return 0.0f;
    const float wh = glm::dot(w, h);
    if (!(wh > 0.0f)) return 0.0f;
    return G1(w) * wh * D(h) / w.z;
}

float TrowbridgeReitz::reflectionPdf(const glm::vec3& wo, const glm::vec3& wi) const {
    const glm::vec3 H = wo + wi;
    const float len = glm::length(H);
    if (!(len > 1e-12f)) return 0.0f;
    const glm::vec3 h = H / len;
    const float oh = glm::dot(wo, h);
    if (!(oh > 0.0f)) return 0.0f;
    return visibleNormalPdf(wo, h) / (4.0f * oh);
}

}  // namespace woven
