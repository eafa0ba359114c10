// The texel fit (core/bake/texel_fit.h) and the lobe mapping under it (lobe_fit.h): one A-S
// lobe gives back its own widths and direction; spreads add as LEAN mapping says; the diffuse
// scale matches the bi-hemispherical albedo of glTF's diffuse as GltfBxdf evaluates it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gltf_bxdf.h"
#include "lobe_fit.h"
#include "texel_fit.h"

namespace woven {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A point of the model: a lobe of exponents (ex, ey) along `axis` (in the tangent plane) around `normal`.
WovenShading point(glm::vec3 normal, glm::vec3 axis, float ex, float ey, glm::vec3 rd = glm::vec3(0.5f), float rs = 0.04f) {
    return {YarnType::Weft, SurfaceBsdf(Frame::fromNormalAndAxis(glm::normalize(normal), axis), AshikhminShirley(ex, ey, rs, rd))};
}

TEST(TexelFit, OneLobeGivesBackItsWidthsAlongAndAcross) {
    // A yarn along +v (a warp end), flat: alpha 0.139 along v (e = 100), 0.707 across (e = 2):
    // KHR_materials_anisotropy's roughness is sqrt(0.139), its direction (the rougher one) +u.
    TexelSums s;
    s.add(point({0, 0, 1}, {0, 1, 0}, 100.0f, 2.0f, {0.5f, 0.25f, 0.125f}));
    const TexelFit t = fitTexel(s);
    const double along = std::sqrt(2.0 / 102.0), across = std::sqrt(2.0 / 4.0);
    EXPECT_FLOAT_EQ(t.coverage, 1.0f);
    EXPECT_NEAR(t.roughness, std::sqrt(along), 1e-5);
    // alpha_t = mix(alpha, 1, strength^2) must give back the width across.
    const double a = double(t.roughness) * t.roughness;
    EXPECT_NEAR(a + (1.0 - a) * t.anisotropy * t.anisotropy, across, 1e-5);
    EXPECT_NEAR(t.direction.x, 1.0f, 1e-6f);
    EXPECT_NEAR(t.direction.y, 0.0f, 1e-6f);
    EXPECT_NEAR(t.normal.z, 1.0f, 1e-6f);
    EXPECT_NEAR(t.baseColor.g / t.baseColor.r, 0.5f, 1e-6f);
    EXPECT_NEAR(t.baseColor.r, diffuseScale() * 0.5f, 1e-6f);
    EXPECT_NEAR(t.rs, 0.04f, 1e-7f);
}

TEST(TexelFit, SpreadsAddAcrossTheFootprintAsLeanMappingSays) {
    // Two flat isotropic lobes (alpha^2 = 2 / (e + 2) = 0.02) tilted +-0.3 along u: the mean
    // normal is up, and the spread along u grows by the normals' own, sin(0.3)^2 = 0.0873:
    // alpha_u^2 = 2 (0.01 + 0.0873), alpha_v^2 = 0.02.
    TexelSums s;
    const float t = 0.3f;
    s.add(point({std::sin(t), 0, std::cos(t)}, {0, 1, 0}, 98.0f, 98.0f));
    s.add(point({-std::sin(t), 0, std::cos(t)}, {0, 1, 0}, 98.0f, 98.0f));
    s.add(std::nullopt);  // a gap: a third of the footprint is see-through
    const TexelFit fit = fitTexel(s);
    EXPECT_NEAR(fit.coverage, 2.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(fit.normal.x, 0.0f, 1e-6f);
    const double smooth = std::sqrt(0.02), rough = std::sqrt(2.0 * (0.01 + std::sin(0.3) * std::sin(0.3)));
    EXPECT_NEAR(double(fit.roughness) * fit.roughness, smooth, 1e-5);
    const double a = smooth;
    EXPECT_NEAR(a + (1.0 - a) * fit.anisotropy * fit.anisotropy, rough, 1e-5);
    EXPECT_NEAR(std::abs(fit.direction.x), 1.0f, 1e-5f);  // rougher along u, where the normals differ

    // A footprint of sums is the sum of its parts: halves added give the whole's fit.
    TexelSums a1, a2, whole;
    for (int i = 0; i < 8; ++i) {
        const WovenShading p = point({0.1f * i, -0.05f * i, 1.0f}, {1, 0.2f * i, 0}, 50.0f + 10 * i, 5.0f);
        (i < 4 ? a1 : a2).add(p);
        whole.add(p);
    }
    a1 += a2;
    const TexelFit x = fitTexel(a1), y = fitTexel(whole);
    EXPECT_NEAR(x.roughness, y.roughness, 1e-6f);
    EXPECT_NEAR(x.anisotropy, y.anisotropy, 1e-6f);
    EXPECT_NEAR(glm::dot(x.normal, y.normal), 1.0f, 1e-6f);
}

TEST(TexelFit, AFootprintOfGapsIsTransparent) {
    TexelSums s;
    s.add(std::nullopt);
    s.add(std::nullopt);
    EXPECT_EQ(fitTexel(s).coverage, 0.0f);
    EXPECT_EQ(fitTexel(TexelSums{}).coverage, 0.0f);
}

TEST(LobeFit, DiffuseScaleMatchesTheAlbedoOfGltfsDiffuseTerm) {
    // glTF's diffuse part of GltfBxdf (base colour 1 minus base colour 0) integrated over both
    // hemispheres by Monte Carlo (cosine-weighted pairs: the mean of f pi), against A-S's exact
    // bi-hemispherical albedo 0.8214 (1 - rs) (lobe_fit.cpp) divided by the scale, at any rs.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto cosine = [&] {
        const double r = std::sqrt(u(rng)), phi = 2.0 * kPi * u(rng);
        return glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(std::max(0.0, 1.0 - r * r))));
    };
    for (float rs : {0.0f, 0.04f, 0.2f}) {
        GltfBxdfInputs white, black;
        white.metallic = black.metallic = 0.0f;
        white.roughness = black.roughness = 0.5f;
        white.specularF0 = black.specularF0 = glm::vec3(rs);
        white.baseColor = glm::vec3(1.0f);
        black.baseColor = glm::vec3(0.0f);
        const GltfBxdf w(white), b(black);
        constexpr int n = 400000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const glm::vec3 wo = cosine(), wi = cosine();
            sum += double(w.eval(wo, wi).g - b.eval(wo, wi).g) * kPi;
        }
        // The integrand lies in [0.6, 1]: the estimate's standard error is below 3.2e-4, the bound
        // 4e-3 over 10 of them, and a scale from the wrong integral (Lambert without 1 - F: 5 %) fails.
        const double gltf = sum / n;
        const double g = 0.5 - 4.0 * (63.0 / 384.0 - 127.0 / 896.0);
        const double ashikhminShirley = 28.0 / (23.0 * kPi) * (1.0 - rs) * (2.0 * kPi * g) * (2.0 * kPi * g) / kPi;
        EXPECT_NEAR(diffuseScale(), ashikhminShirley / gltf, 4e-3) << "rs " << rs;
    }
}

TEST(LobeFit, IorGivesBackF0) {
    for (float rs : {0.0f, 0.04f, 0.1f}) {
        const float ior = iorForF0(rs), r = (ior - 1.0f) / (ior + 1.0f);
        EXPECT_NEAR(r * r, rs, 1e-6f);
    }
    EXPECT_NEAR(iorForF0(0.04f), 1.5f, 1e-6f);
}

}  // namespace
}  // namespace woven
