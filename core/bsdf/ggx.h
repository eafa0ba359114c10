#pragma once
// The Trowbridge-Reitz (GGX) microfacet distribution of the glTF BRDF (glTF 2.0 appendix B), with
// KHR_materials_anisotropy's two roughnesses, in a local frame with z = the normal and x = the
// direction of alphaX: D, the height-correlated Smith visibility V = G2 / (4 |n.wo| |n.wi|), and
// sampling of the visible normals (Heitz 2018).
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace woven {

class TrowbridgeReitz {
public:
    // alpha = roughness^2, clamped to kMinAlpha: a mirror is approximated by a very sharp lobe,
    // since no BSDF in woven is a delta function.
    explicit TrowbridgeReitz(float alpha) : TrowbridgeReitz(alpha, alpha) {}
    // alphaX along the frame's x axis, alphaY along y, each clamped to [kMinAlpha, 1].
    TrowbridgeReitz(float alphaX, float alphaY) : alphaX_(clampAlpha(alphaX)), alphaY_(clampAlpha(alphaY)) {}
    static constexpr float kMinAlpha = 1e-3f;

    float alphaX() const { return alphaX_; }
    float alphaY() const { return alphaY_; }
    float D(const glm::vec3& h) const;
    float lambda(const glm::vec3& w) const;
    float G1(const glm::vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
    // The spec's V_GGX; zero when either direction is on the horizon.
    float visibility(const glm::vec3& wo, const glm::vec3& wi) const;

    // A normal h visible from w (w.z > 0), with density visibleNormalPdf(w, h).
    glm::vec3 sampleVisibleNormal(const glm::vec3& w, const glm::vec2& u) const;
    float visibleNormalPdf(const glm::vec3& w, const glm::vec3& h) const;
    // Density of wi = reflect(wo, h) for h sampled from wo's visible normals.
    float reflectionPdf(const glm::vec3& wo, const glm::vec3& wi) const;

private:
    static float clampAlpha(float alpha) { return std::clamp(std::isfinite(alpha) ? alpha : 1.0f, kMinAlpha, 1.0f); }
    // |(alphaX w.x, alphaY w.y, w.z)|: the length of w in the stretched configuration.
    float stretchedLength(const glm::vec3& w) const;

    float alphaX_, alphaY_;
};

// Schlick's Fresnel from the cosine between the view and the half vector.
inline float schlickWeight(float cosTheta) {
    const float m = glm::clamp(1.0f - cosTheta, 0.0f, 1.0f);
    return (m * m) * (m * m) * m;
}

}  // namespace woven
