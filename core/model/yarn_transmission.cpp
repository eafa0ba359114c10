#include "yarn_transmission.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"
#include "sampling.h"

namespace woven {

namespace {
float pow5(float x) { return (x * x) * (x * x) * x; }
// A-S's diffuse factor for one direction: the share that passes its specular coat, up to 1 - R_s.
float coatPassing(float mu) { return 1.0f - pow5(1.0f - 0.5f * mu); }

// wo and wi on opposite sides, the one below mirrored up: its half vector is this sum (unnormalised).
glm::vec3 mirroredHalf(const glm::vec3& wo, const glm::vec3& wi) {
    return {wo.x + wi.x, wo.y + wi.y, std::fabs(wo.z) + std::fabs(wi.z)};
}
bool opposite(const glm::vec3& wo, const glm::vec3& wi) {
    return (wo.z > 0.0f && wi.z < 0.0f) || (wo.z < 0.0f && wi.z > 0.0f);
}
}  // namespace

glm::vec3 yarnTransmittance(const glm::vec3& rd, float t) {
    const float peak = std::max(rd.r, std::max(rd.g, rd.b));
    if (!(peak > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 hue = rd / peak;
    return t * (1.0f - rd) * hue * hue;
}

glm::vec3 YarnTransmission::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (!opposite(wo, wi)) return glm::vec3(0.0f);
    const float mo = std::fabs(wo.z), mi = std::fabs(wi.z);
    float lobe = (1.0f - gloss_) * (28.0f / (23.0f * kPi));
    const glm::vec3 H = mirroredHalf(wo, wi);
    const float len2 = glm::dot(H, H);
    if (gloss_ > 0.0f && len2 > 1e-24f) {
        // The specular lobe without its Fresnel factor, p_h / (4 (h.k) max(mu_o, mu_i)); h.k as in
        // AshikhminShirley::eval, |k1 + k2| / 2, symmetric in the two directions.
        const float hk = 0.5f * std::sqrt(len2);
        lobe += gloss_ * specular_.halfVectorPdf(H) / (4.0f * hk * std::max(mo, mi));
    }
    return transmittance_ * ((1.0f - specular_.shape().rs) * coatPassing(mo) * coatPassing(mi) * lobe);
}

float YarnTransmission::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (!opposite(wo, wi)) return 0.0f;
    float p = (1.0f - gloss_) * std::fabs(wi.z) / kPi;
    const glm::vec3 H = mirroredHalf(wo, wi);
    const float len2 = glm::dot(H, H);
    if (gloss_ > 0.0f && len2 > 1e-24f) p += gloss_ * specular_.halfVectorPdf(H) / (2.0f * std::sqrt(len2));
    return p;
}

std::optional<BsdfSample> YarnTransmission::sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
    if (wo.z == 0.0f || !std::isfinite(wo.z)) return std::nullopt;
    const float side = wo.z > 0.0f ? 1.0f : -1.0f;
    glm::vec3 w;  // on wo's side, mirrored below at the end (the mirror keeps solid angle)
    if (uc < gloss_) {
        const glm::vec3 up(wo.x, wo.y, std::fabs(wo.z));
        const glm::vec3 h = specular_.sampleHalfVector(u);
        const float oh = glm::dot(up, h);
        if (oh <= 0.0f) return std::nullopt;
        w = 2.0f * oh * h - up;
    } else {
        w = sampleCosineHemisphere(u);
    }
    if (w.z <= 0.0f) return std::nullopt;
    BsdfSample s;
    s.wi = glm::vec3(w.x, w.y, -side * w.z);
    s.pdf = pdf(wo, s.wi);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.f = eval(wo, s.wi);
    s.weight = s.f * (w.z / s.pdf);
    return s;
}

}  // namespace woven
