#include "sheen_lobe.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "math_constants.h"

namespace woven {

namespace {
// Conty Estevez and Kulla's fit of the Charlie Lambda, interpolated in (1 - alpha)^2.
float fitL(float x, float alpha) {
    const float t = (1.0f - alpha) * (1.0f - alpha);
    const float a = 21.5473f + (25.3245f - 21.5473f) * t;
    const float b = 3.82987f + (3.32435f - 3.82987f) * t;
    const float c = 0.19823f + (0.16801f - 0.19823f) * t;
    const float d = -1.97760f + (-1.27393f + 1.97760f) * t;
    const float e = -4.32054f + (-4.85967f + 4.32054f) * t;
    return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}

float lambda(float cosTheta, float alpha) {
    const float c = std::abs(cosTheta);
    return c < 0.5f ? std::exp(fitL(c, alpha)) : std::exp(2.0f * fitL(0.5f, alpha) - fitL(1.0f - c, alpha));
}

// E(cos theta, roughness) on a kSize x kSize grid over [0, 1]^2 (roughness clamped as the lobe
// clamps it). Integrated by the midpoint rule over (cos theta_i, phi_i), phi folded onto [0, pi]
// by the lobe's mirror symmetry; tests/bsdf checks it against a finer integral.
constexpr int kSize = SheenLobe::kAlbedoTableSize;
using AlbedoTable = std::array<float, kSize * kSize>;

AlbedoTable integrateAlbedo() {
    AlbedoTable table{};
    constexpr int kTheta = 96, kPhi = 48;
    for (int r = 0; r < kSize; ++r) {
        const SheenLobe lobe(glm::vec3(1.0f), float(r) / (kSize - 1));
        for (int m = 0; m < kSize; ++m) {
            const float cosO = std::max(float(m) / (kSize - 1), 1e-3f);
            const glm::vec3 wo(std::sqrt(1.0f - cosO * cosO), 0.0f, cosO);
            double sum = 0.0;
            for (int i = 0; i < kTheta; ++i) {
                const float cosI = (i + 0.5f) / kTheta;
                const float sinI = std::sqrt(1.0f - cosI * cosI);
                for (int j = 0; j < kPhi; ++j) {
                    const float phi = kPi * (j + 0.5f) / kPhi;
                    const glm::vec3 wi(sinI * std::cos(phi), sinI * std::sin(phi), cosI);
                    sum += double(lobe.eval(wo, wi).x) * cosI;
                }
            }
            // d omega = d cos theta d phi; the fold doubles the phi range.
            table[size_t(r) * kSize + m] = float(sum * (1.0 / kTheta) * (2.0 * kPi / kPhi));
        }
    }
    return table;
}
}  // namespace

SheenLobe::SheenLobe(const glm::vec3& color, float roughness)
    : color_(glm::max(color, glm::vec3(0.0f))),
      roughness_(std::clamp(std::isfinite(roughness) ? roughness : 1.0f, kMinRoughness, 1.0f)),
      alpha_(roughness_ * roughness_),
      maxColor_(std::max({color_.r, color_.g, color_.b})) {}

float SheenLobe::distribution(const glm::vec3& h) const {
    const float sin2 = std::min(h.x * h.x + h.y * h.y, 1.0f);
    const float invAlpha = 1.0f / alpha_;
    return (2.0f + invAlpha) * std::pow(sin2, 0.5f * invAlpha) / (2.0f * kPi);
}

float SheenLobe::visibility(float cosO, float cosI) const {
    return 1.0f / ((1.0f + lambda(cosO, alpha_) + lambda(cosI, alpha_)) * (4.0f * cosO * cosI));
}

glm::vec3 SheenLobe::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 H = wo + wi;
    const float len = glm::length(H);
    if (!(len > 1e-12f)) return glm::vec3(0.0f);
    return color_ * (distribution(H / len) * visibility(wo.z, wi.z));
}

const AlbedoTable& SheenLobe::albedoTable() {
    static const AlbedoTable table = integrateAlbedo();
    return table;
}

float SheenLobe::albedo(float cosTheta) const {
    const AlbedoTable& table = albedoTable();
    const float x = std::clamp(std::abs(cosTheta), 0.0f, 1.0f) * (kSize - 1);
    const float y = roughness_ * (kSize - 1);
    const int x0 = std::min(int(x), kSize - 2), y0 = std::min(int(y), kSize - 2);
    const float tx = x - x0, ty = y - y0;
    const auto at = [&](int i, int j) { return table[size_t(j) * kSize + i]; };
    return (1.0f - ty) * ((1.0f - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) +
           ty * ((1.0f - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
}

float SheenLobe::baseScale(float cosTheta) const {
    if (!active()) return 1.0f;
    return std::clamp(1.0f - maxColor_ * albedo(cosTheta), 0.0f, 1.0f);
}

}  // namespace woven
