#include "ashikhmin_shirley.h"

#include <algorithm>
#include <cmath>

#include "sampling.h"

namespace woven {

namespace {
constexpr float kPi = 3.14159265358979f;

float pow5(float x) { return (x * x) * (x * x) * x; }

// (n.h)^N from sin^2(theta_h): log1p keeps exponents up to 1e5 accurate where n.h rounds to 1.
float cosPowN(float sin2, float N) {
    if (N <= 0.0f) return 1.0f;  // not 0 * log(0) = NaN where h reaches the horizon
    return std::exp(N * 0.5f * std::log1p(-std::min(sin2, 1.0f)));
}
}  // namespace

AshikhminShirley::AshikhminShirley(float ex, float ey, float rs, const glm::vec3& rd)
    : ex_(ex), ey_(ey), rs_(rs), rd_(rd), specNorm_(std::sqrt((ex + 1.0f) * (ey + 1.0f))) {
    // Lobe choice by the reflectance each lobe carries; some diffuse sampling stays whenever
    // there is a diffuse term so that its pdf never vanishes where it is non-zero.
    const float spec = rs;
    const float diff = (1.0f - rs) * (rd.r + rd.g + rd.b) / 3.0f;
    if (diff <= 0.0f) specularProb_ = 1.0f;
    else specularProb_ = std::min(0.9f, 0.25f + 0.75f * spec / (spec + diff));
}

float AshikhminShirley::exponent(const glm::vec3& h) const {
    const float sx = h.x * h.x, sy = h.y * h.y, s = sx + sy;
    return s > 0.0f ? (ex_ * sx + ey_ * sy) / s : ex_;  // phi is irrelevant at h = n
}

float AshikhminShirley::halfVectorPdf(const glm::vec3& h) const {
    if (h.z <= 0.0f) return 0.0f;
    return specNorm_ / (2.0f * kPi) * cosPowN(h.x * h.x + h.y * h.y, exponent(h));
}

glm::vec3 AshikhminShirley::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 diffuse = (28.0f / (23.0f * kPi)) * rd_ * (1.0f - rs_) *
                              (1.0f - pow5(1.0f - 0.5f * wo.z)) * (1.0f - pow5(1.0f - 0.5f * wi.z));
    const glm::vec3 H = wo + wi;
    const float len = glm::length(H);
    if (!(len > 1e-12f)) return diffuse;
    const glm::vec3 h = H / len;
    // h.k = |k1 + k2| / 2 for unit k1, k2: symmetric in the two directions, so reciprocal, and free
    // of the cancellation that makes dot(h, k) lose its digits as h.k -> 0 (grazing opposite k1, k2).
    const float hk = 0.5f * len;
    const float fresnel = rs_ + (1.0f - rs_) * pow5(1.0f - hk);
    const float spec = specNorm_ / (8.0f * kPi) * cosPowN(h.x * h.x + h.y * h.y, exponent(h)) /
                       (hk * std::max(wo.z, wi.z)) * fresnel;
    return diffuse + glm::vec3(spec);
}

float AshikhminShirley::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float p = (1.0f - specularProb_) * wi.z / kPi;
    const glm::vec3 H = wo + wi;
    const float len = glm::length(H);
    if (specularProb_ > 0.0f && len > 1e-12f) {
        const float ok = 0.5f * len;  // wo.h, as in eval()
        p += specularProb_ * halfVectorPdf(H / len) / (4.0f * ok);
    }
    return p;
}

glm::vec3 AshikhminShirley::sampleHalfVector(const glm::vec2& u) const {
    // phi in the first quadrant by A-S's tan mapping (written with atan2, which stays finite
    // at u = 1), mirrored into the other three with continuous sub-ranges of u.x.
    const float a = u.x * 4.0f;
    const int quadrant = std::min(int(a), 3);
    float uq = a - float(quadrant);
    if (quadrant == 1 || quadrant == 3) uq = 1.0f - uq;
    const float angle = 0.5f * kPi * uq;
    float phi = std::atan2(std::sqrt(ex_ + 1.0f) * std::sin(angle), std::sqrt(ey_ + 1.0f) * std::cos(angle));
    phi = std::clamp(phi, 0.0f, 0.5f * kPi);
    if (quadrant == 1) phi = kPi - phi;
    else if (quadrant == 2) phi = kPi + phi;
    else if (quadrant == 3) phi = 2.0f * kPi - phi;
    const float cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    const float N = ex_ * cosPhi * cosPhi + ey_ * sinPhi * sinPhi;
    // cos(theta) = (1 - u.y)^(1 / (N + 1)); 1 - cos(theta) through expm1 keeps sin(theta)
    // accurate when N is large and cos(theta) rounds to 1.
    const float logCos = std::log1p(-u.y) / (N + 1.0f);
    const float oneMinusCos = -std::expm1(logCos);
    const float cosTheta = 1.0f - oneMinusCos;
    const float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (1.0f + cosTheta)));
    return {sinTheta * cosPhi, sinTheta * sinPhi, cosTheta};
}

std::optional<BsdfSample> AshikhminShirley::sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
    if (wo.z <= 0.0f) return std::nullopt;
    glm::vec3 wi;
    if (uc < specularProb_) {
        const glm::vec3 h = sampleHalfVector(u);
        const float oh = glm::dot(wo, h);
        if (oh <= 0.0f) return std::nullopt;
        wi = 2.0f * oh * h - wo;
    } else {
        wi = sampleCosineHemisphere(u);
    }
    if (wi.z <= 0.0f) return std::nullopt;
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf(wo, wi);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.f = eval(wo, wi);
    s.weight = s.f * (wi.z / s.pdf);
    return s;
}

}  // namespace woven
