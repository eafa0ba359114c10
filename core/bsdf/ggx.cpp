#include "ggx.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
constexpr float kPi = 3.14159265358979f;
}

TrowbridgeReitz::TrowbridgeReitz(float alpha) : alpha_(std::clamp(std::isfinite(alpha) ? alpha : 1.0f, kMinAlpha, 1.0f)) {}

float TrowbridgeReitz::D(const glm::vec3& h) const {
    if (h.z <= 0.0f) return 0.0f;
    // alpha^2 cos^2 + sin^2 instead of cos^2 (alpha^2 - 1) + 1: no cancellation near h = n,
    // where a small alpha puts all of D.
    const float a2 = alpha_ * alpha_;
    const float d = a2 * h.z * h.z + (h.x * h.x + h.y * h.y);
    return a2 / (kPi * d * d);
}

float TrowbridgeReitz::lambda(const glm::vec3& w) const {
    const float cos2 = w.z * w.z;
    const float sin2 = w.x * w.x + w.y * w.y;
    if (!(cos2 > 0.0f)) return std::numeric_limits<float>::infinity();
    const float tan2 = sin2 / cos2;
    return 0.5f * (std::sqrt(1.0f + alpha_ * alpha_ * tan2) - 1.0f);
}

float TrowbridgeReitz::visibility(const glm::vec3& wo, const glm::vec3& wi) const {
    const float no = std::abs(wo.z), ni = std::abs(wi.z);
    if (!(no > 0.0f) || !(ni > 0.0f)) return 0.0f;
    const float a2 = alpha_ * alpha_;
    const float denom = ni * std::sqrt(no * no * (1.0f - a2) + a2) + no * std::sqrt(ni * ni * (1.0f - a2) + a2);
    return 0.5f / denom;
}

glm::vec3 TrowbridgeReitz::sampleVisibleNormal(const glm::vec3& w, const glm::vec2& u) const {
    // Heitz 2018: stretch to the unit-roughness configuration, sample the projected disk of the
    // visible hemisphere, unstretch.
    const glm::vec3 wh = glm::normalize(glm::vec3(alpha_ * w.x, alpha_ * w.y, w.z));
    const float len2 = wh.x * wh.x + wh.y * wh.y;
    const glm::vec3 t1 = len2 > 0.0f ? glm::vec3(-wh.y, wh.x, 0.0f) / std::sqrt(len2) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(wh, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + wh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * wh;
    return glm::normalize(glm::vec3(alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)));
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
