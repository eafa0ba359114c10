// The directional albedo E(wo) = int D V cos(theta_i) dwi of the GGX lobe alone (a white metal:
// base colour 1, metallic 1, so F = 1), computed twice:
//  (a) deterministic quadrature in double of the reference D and V (reference_gltf_brdf.h), in
//      the variables of the GGX slope distribution: with tan(theta_h) = alpha tan(t),
//      D(h) cos(theta_h) dw_h = sin(t) cos(t) dt dphi / pi, smooth for every alpha, and
//      E = int int sin t cos t / pi * 4 V (wo.h) (wi.z) / h.z dt dphi
//      over the half vectors whose reflection stays above the horizon, which for each phi is
//      theta_h < (delta(phi) + pi / 2) / 2 with tan(delta) = sin(theta_o) cos(phi) / cos(theta_o)
//      (wi.z = A cos(2 theta_h - delta), A > 0). Adaptive Gauss-Legendre to an absolute 1e-8
//      (a 10 times looser run agrees to 1e-6).
//  (b) Monte Carlo with GltfBxdf::sample's weights (fixed seed): for this lobe the weight is
//      G2 / G1(wo) in [0, 1], so the mean of N = 4e4 draws has a standard error sigma < 2.5e-3.
// They must agree within 4 sigma + 1e-4 (a false alarm rate of 6e-5 per case if the seed were
// drawn afresh; the 1e-4 covers the code's float arithmetic).
//
// The figures 1 - E are the energy the single-scattering GGX lobe loses to the multiple
// scattering it does not model (glTF's appendix B does not compensate it, and neither does
// GltfBxdf): printed as a table for docs/MATERIALS.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_test_util.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;
using gltfref::kPi;

constexpr double kTolerance = 1e-8;

// E(theta_o) of GGX with this alpha, by quadrature (a), to an absolute `tolerance`.
double ggxAlbedo(double alpha, double cosO, double tolerance = kTolerance) {
    const double sinO = std::sqrt(std::max(0.0, 1.0 - cosO * cosO));
    const glm::dvec3 wo(sinO, 0.0, cosO);
    const auto overT = [&](double phi) {
        const double delta = std::atan2(sinO * std::cos(phi), cosO);
        const double thetaMax = 0.5 * (delta + 0.5 * kPi);
        const double tMax = std::atan(std::tan(thetaMax) / alpha);
        return adaptiveGauss([&](double t) {
            const double thetaH = std::atan(alpha * std::tan(t));
            const glm::dvec3 h(std::sin(thetaH) * std::cos(phi), std::sin(thetaH) * std::sin(phi), std::cos(thetaH));
            const double oh = glm::dot(wo, h);
            const glm::dvec3 wi = 2.0 * oh * h - wo;
            if (wi.z <= 0.0) return 0.0;
            const double v = gltfref::ggxV(alpha, wi.z, wo.z, glm::dot(h, wi), oh);
            return std::sin(t) * std::cos(t) / kPi * 4.0 * v * oh * wi.z / h.z;
        }, 0.0, tMax, 0.1 * tolerance);
    };
    return 2.0 * adaptiveGauss(overT, 0.0, kPi, 0.5 * tolerance);  // even in phi
}

struct MonteCarlo {
    double mean, standardError;
};

MonteCarlo sampledAlbedo(float roughness, double cosO, uint64_t seed) {
    GltfBxdfInputs in;
    in.baseColor = glm::vec3(1.0f);
    in.metallic = 1.0f;
    in.roughness = roughness;
    const GltfBxdf bxdf(in);
    const glm::vec3 wo = toFloatUnit({std::sqrt(std::max(0.0, 1.0 - cosO * cosO)), 0.0, cosO});
    TestRng rng(seed);
    constexpr int kDraws = 40000;
    double sum = 0.0, sum2 = 0.0;
    for (int n = 0; n < kDraws; ++n) {
        const auto s = bxdf.sample(wo, rng.u2(), rng.u());
        const double w = s ? double(s->weight.r) : 0.0;
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / kDraws;
    return {mean, std::sqrt(std::max(0.0, sum2 / kDraws - mean * mean) / kDraws)};
}


TEST(GgxAlbedo, QuadratureIsConvergedAndOneForAMirror) {
    // A run to a 10 times looser tolerance agrees to 1e-6 (the adaptive rule's stopping test is
    // a heuristic: at alpha = 1e-3 it stops at a few 1e-7 rather than at the 1e-7 asked for).
    for (double alpha : {1e-3, 0.0625, 0.25, 1.0})
        for (double cosO : {1.0, 0.5, 0.1, 0.01}) {
            const double usual = ggxAlbedo(alpha, cosO), loose = ggxAlbedo(alpha, cosO, 10.0 * kTolerance);
            EXPECT_NEAR(loose, usual, 1e-6) << "alpha " << alpha << " cos " << cosO;
        }
    // At alpha = 1e-3 the lobe is nearly a mirror, which loses only what the masking of a
    // surface of slopes ~1e-3 hides: E = 1 - O(alpha^2 tan^2 theta), 1 to 1e-5 at 0 and 60 deg.
    EXPECT_NEAR(ggxAlbedo(1e-3, 1.0), 1.0, 1e-5);
    EXPECT_NEAR(ggxAlbedo(1e-3, 0.5), 1.0, 1e-5);
}

TEST(GgxAlbedo, QuadratureAgreesWithSampledWeights) {
    uint64_t seed = 3000;
    for (float roughness : {0.05f, 0.25f, 0.5f, 0.75f, 1.0f})
        for (double degrees : {0.0, 30.0, 60.0, 75.0, 85.0, 89.0}) {
            const double cosO = std::cos(degrees * kPi / 180.0);
            const double alpha = gltfref::alphaOf(roughness);
            const double quadrature = ggxAlbedo(alpha, cosO);
            const MonteCarlo mc = sampledAlbedo(roughness, cosO, ++seed);
            EXPECT_NEAR(mc.mean, quadrature, 4.0 * mc.standardError + 1e-4)
                << "roughness " << roughness << " theta " << degrees << " deg (sigma " << mc.standardError << ")";
            EXPECT_LE(quadrature, 1.0);
        }
}

TEST(GgxAlbedo, EnergyLossTable) {
    // 1 - E(theta_o) for roughness r (alpha = r^2), and 1 - E_avg with the cosine-weighted
    // average E_avg = 2 int_0^1 E(mu) mu dmu (Kulla and Conty's measure of the loss over all
    // incident directions: what a white furnace loses at each bounce).
    const double thetas[] = {0.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0};
    std::printf("[ GGX energy loss ] 1 - directional albedo of a white metal (F = 1), single scattering only\n");
    std::printf("[ GGX energy loss ] roughness |");
    for (double t : thetas) std::printf(" %5.0f deg", t);
    std::printf(" | cosine-weighted average\n");
    double previousAverage = -1.0;
    for (double roughness : {0.25, 0.5, 0.75, 1.0}) {
        const double alpha = roughness * roughness;
        std::printf("[ GGX energy loss ] %9.2f |", roughness);
        for (double t : thetas) std::printf(" %8.4f", 1.0 - ggxAlbedo(alpha, std::cos(t * kPi / 180.0)));
        const auto averageWith = [&](int panels) {
            return 2.0 * compositeGauss([&](double mu) { return ggxAlbedo(alpha, mu) * mu; }, 0.0, 1.0, panels);
        };
        const double average = averageWith(4);
        EXPECT_NEAR(average, averageWith(2), 1e-5);  // E(mu) is smooth enough for 32 nodes
        std::printf(" | %8.4f\n", 1.0 - average);
        // The loss grows with roughness.
        EXPECT_GT(1.0 - average, previousAverage);
        previousAverage = 1.0 - average;
    }
}

}  // namespace
}  // namespace woven
