#include "ashikhmin_shirley.h"

#include <algorithm>
#include <cmath>

#include "fast_math.h"
#include "math_constants.h"
#include "sampling.h"

namespace woven {

namespace {
float pow5(float x) { return (x * x) * (x * x) * x; }

// e^x - 1, accurate where e^x rounds to 1: the Taylor series near 0 (|x|^9 / 9! < 2e-8 relative
// for |x| < 0.35), else fastExp.
float expm1(float x) {
    if (std::fabs(x) >= 0.35f) return fastExp(x) - 1.0f;
    return x * (1.0f + x * (0.5f + x * (1.0f / 6 + x * (1.0f / 24 + x * (1.0f / 120 + x * (1.0f / 720 + x * (1.0f / 5040 + x * (1.0f / 40320))))))));
}
}  // namespace

LobeShape::LobeShape(float ex, float ey, float rs)
    : ex(ex), ey(ey), rs(rs), sqrtEx1(std::sqrt(ex + 1.0f)), sqrtEy1(std::sqrt(ey + 1.0f)),
      specNorm(sqrtEx1 * sqrtEy1) {}

float AshikhminShirley::specularProbability(float rs, const glm::vec3& rd) {
    // Lobe choice by the reflectance each lobe carries; some diffuse sampling stays whenever
    // there is a diffuse term so that its pdf never vanishes where it is non-zero.
    const float diff = (1.0f - rs) * (rd.r + rd.g + rd.b) / 3.0f;
    if (diff <= 0.0f) return 1.0f;
    return std::min(0.9f, 0.25f + 0.75f * rs / (rs + diff));
}

// (n.h)^N with N = (e_x h_x^2 + e_y h_y^2) / (h_x^2 + h_y^2), from the unnormalised half vector H
// and 1 / |H|^2. As exp(N / 2 ln(1 - s)) with s = sin^2(theta_h) = (H_x^2 + H_y^2) / |H|^2:
// N ln(1 - s) = -(e_x H_x^2 + e_y H_y^2) / |H|^2 * L(s), L(s) = -ln(1 - s) / s, so N needs no
// division of its own, and L's series keeps exponents up to 1e5 accurate where n.h rounds to 1.
float AshikhminShirley::cosPowN(const glm::vec3& H, float invLen2) const {
    const float x2 = H.x * H.x, y2 = H.y * H.y;
    const float a = (shape_.ex * x2 + shape_.ey * y2) * invLen2;
    if (!(a > 0.0f)) return 1.0f;  // N = 0 (or h = n): not 0 * log(0) = NaN at the horizon
    const float s = (x2 + y2) * invLen2;
    if (s >= 1.0f) return 0.0f;
    // L(s) = 1 + s/2 + s^2/3 + ...: 8 terms leave s^8 / 9 < 1.2e-9 for s < 0.1.
    const float L = s < 0.1f ? 1.0f + s * (1.0f / 2 + s * (1.0f / 3 + s * (1.0f / 4 + s * (1.0f / 5 + s * (1.0f / 6 + s * (1.0f / 7 + s * (1.0f / 8)))))))
                             : -fastLog(1.0f - s) / s;
    return fastExp(-0.5f * a * L);
}

float AshikhminShirley::halfVectorPdf(const glm::vec3& h) const {
    if (h.z <= 0.0f) return 0.0f;
    return shape_.specNorm / (2.0f * kPi) * cosPowN(h, 1.0f / glm::dot(h, h));
}

glm::vec3 AshikhminShirley::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const float rs = shape_.rs;
    const glm::vec3 diffuse = (28.0f / (23.0f * kPi)) * rd_ * (1.0f - rs) *
                              (1.0f - pow5(1.0f - 0.5f * wo.z)) * (1.0f - pow5(1.0f - 0.5f * wi.z));
    const glm::vec3 H = wo + wi;
    const float len2 = glm::dot(H, H);
    if (!(len2 > 1e-24f)) return diffuse;
    // h.k = |k1 + k2| / 2 for unit k1, k2: symmetric in the two directions, so reciprocal, and free
    // of the cancellation that makes dot(h, k) lose its digits as h.k -> 0 (grazing opposite k1, k2).
    const float hk = 0.5f * std::sqrt(len2);
    const float fresnel = rs + (1.0f - rs) * pow5(1.0f - hk);
    const float spec = shape_.specNorm / (8.0f * kPi) * cosPowN(H, 1.0f / len2) * fresnel / (hk * std::max(wo.z, wi.z));
    return diffuse + glm::vec3(spec);
}

float AshikhminShirley::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    float p = (1.0f - specularProb_) * wi.z / kPi;
    const glm::vec3 H = wo + wi;
    const float len2 = glm::dot(H, H);
    if (specularProb_ > 0.0f && len2 > 1e-24f && H.z > 0.0f) {
        const float ok = 0.5f * std::sqrt(len2);  // wo.h, as in eval()
        p += specularProb_ * halfVectorPdf(H) / (4.0f * ok);
    }
    return p;
}

glm::vec3 AshikhminShirley::sampleHalfVector(const glm::vec2& u) const {
    // phi in the first quadrant by A-S's tan mapping, tan(phi) = sqrt((e_x + 1)/(e_y + 1)) tan(angle):
    // (cos phi, sin phi) is the unit vector along (sqrt(e_y + 1) cos(angle), sqrt(e_x + 1) sin(angle)),
    // finite at u = 1 and without an inverse tangent. Mirrored into the other three quadrants
    // with continuous sub-ranges of u.x.
    const float a = u.x * 4.0f;
    const int quadrant = std::min(int(a), 3);
    float uq = a - float(quadrant);
    if (quadrant == 1 || quadrant == 3) uq = 1.0f - uq;
    float sinAngle, cosAngle;
    fastSinCos(0.5f * kPi * uq, &sinAngle, &cosAngle);
    const float px = shape_.sqrtEy1 * cosAngle, py = shape_.sqrtEx1 * sinAngle;
    const float inv = 1.0f / std::sqrt(px * px + py * py);
    float cosPhi = px * inv, sinPhi = py * inv;
    if (quadrant == 1 || quadrant == 2) cosPhi = -cosPhi;
    if (quadrant >= 2) sinPhi = -sinPhi;
    const float N = shape_.ex * cosPhi * cosPhi + shape_.ey * sinPhi * sinPhi;
    // cos(theta) = (1 - u.y)^(1 / (N + 1)); 1 - cos(theta) through expm1 keeps sin(theta)
    // accurate when N is large and cos(theta) rounds to 1.
    const float logCos = fastLog1p(-u.y) / (N + 1.0f);
    const float oneMinusCos = -expm1(logCos);
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
