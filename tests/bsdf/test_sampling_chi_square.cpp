// Goodness of fit of GltfBxdf::sample() against GltfBxdf::pdf(), as tests/model's chi-square
// test does it for the woven lobe (and with its tools, direction_domain.h): histogram sampled
// directions over the cells of a direction domain, integrate pdf() over each cell numerically,
// Pearson's chi-square with cells expected below 5 samples pooled.
//
// Both hemispheres. The thin-walled transmission samples directions below the surface; they
// are binned by their mirror image M(wi) = (x, y, -z) in a second histogram over the same
// domain, whose expected counts integrate pdf(wo, M(w)). The two histograms make one test, so
// that a sample put on the wrong side counts. Samples the sampler rejects (a GGX reflection
// below the horizon) are not binned: pdf() is the density of the directions it returns, a
// sub-probability density, and the expected counts are N times its integral over each cell.
//
// Domains. (cos theta, phi) of wi for lobes with alpha >= 0.09 (several cells wide), and for
// every case the slopes of the half vector scaled by 1 / alpha of the sharpest lobe
// (direction_domain.h's halfVectorDomain), where a GGX lobe of alpha = 1e-3 still spans many
// cells and the diffuse and sheen parts spread over the outer ones.
//
// Sizes: 1e5 samples per case over 24 x 24 cells per hemisphere, the cells' integrals by
// direction_domain.h's adaptive Gauss-Legendre (order 3, up to 3 splittings, to 1e-4 relative:
// well under the Poisson noise of the largest cell, sqrt(1e5 / 50) / (1e5 / 50) = 2 %).
//
// Significance. Each case uses its own fixed seed; the suite should wrongly fail with
// probability alpha = 1 % if the seeds were drawn afresh. Both domains test the same samples,
// so the M tests are not independent: Bonferroni's alpha_i = alpha / M (valid under any
// dependence) rather than Sidak's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bsdf_test_util.h"
#include "direction_domain.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr int kSamples = 100000;
constexpr int kResolution = 24;

struct Case {
    const char* name;
    Material m;
};

std::vector<Case> cases() {
    std::vector<Case> all;
    const auto add = [&](const char* name, auto change) {
        Material m;
        m.baseColor = {0.6, 0.5, 0.4};
        m.metallic = 0.0;
        m.roughness = 0.5;
        change(m);
        all.push_back({name, m});
    };
    add("rough dielectric", [](Material& m) { m.roughness = 0.6; });
    add("smooth dielectric", [](Material& m) { m.roughness = 0.1; });
    add("mirror dielectric (alpha 1e-3)", [](Material& m) { m.roughness = 0.0; m.ior = 1.8; });
    add("black dielectric", [](Material& m) { m.baseColor = glm::dvec3(0.0); m.roughness = 0.4; });
    add("metal", [](Material& m) { m.metallic = 1.0; m.roughness = 0.3; m.baseColor = {0.9, 0.6, 0.3}; });
    add("sheen", [](Material& m) { m.sheenColor = {1.0, 0.8, 0.9}; m.sheenRoughness = 0.3; m.baseColor = {0.2, 0.1, 0.1}; });
    add("clearcoat (sharp)", [](Material& m) {
        m.roughness = 0.7;
        m.clearcoat = 1.0;
        m.clearcoatRoughness = 0.1;
    });
    add("clearcoat (tilted normal)", [](Material& m) {
        m.roughness = 0.8;
        m.clearcoat = 0.8;
        m.clearcoatRoughness = 0.4;
        m.clearcoatNormal = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    });
    add("clearcoat (tilted normal) over transmission", [](Material& m) {
        m.roughness = 0.6;
        m.transmission = 0.7;
        m.clearcoat = 1.0;
        m.clearcoatRoughness = 0.3;
        m.clearcoatNormal = glm::normalize(glm::dvec3(-0.2, 0.3, 1.0));
    });
    add("transmission (rough)", [](Material& m) { m.transmission = 0.8; m.roughness = 0.4; m.transmittance = {0.9, 0.7, 0.5}; });
    add("transmission (smooth)", [](Material& m) { m.transmission = 1.0; m.roughness = 0.1; });
    add("everything", [](Material& m) {
        m.metallic = 0.3;
        m.transmission = 0.5;
        m.sheenColor = {0.5, 0.5, 0.3};
        m.sheenRoughness = 0.5;
        m.clearcoat = 0.5;
        m.clearcoatRoughness = 0.3;
        m.ior = 1.3;
        m.specular = 0.7;
    });
    return all;
}

const double kThetaDegrees[] = {10.0, 50.0, 85.0};

// The sharpest GGX lobe of a material, which sets the half-vector domain's scale.
double sharpestAlpha(const Material& m) {
    double a = gltfref::alphaOf(m.roughness);
    if (m.clearcoat > 0.0) a = std::min(a, gltfref::alphaOf(m.clearcoatRoughness));
    return a;
}
bool sphericalToo(const Material& m) { return sharpestAlpha(m) >= 0.09; }

int countTests() {
    int n = 0;
    for (const Case& c : cases()) n += 1 + sphericalToo(c.m);
    return n * int(std::size(kThetaDegrees));
}
const double kSignificance = 0.01 / countTests();

uint64_t caseSeed(size_t caseIndex, double degrees) {
    uint64_t h = 0xb5df5eedULL ^ (uint64_t(caseIndex) << 32);
    uint64_t bits;
    std::memcpy(&bits, &degrees, sizeof bits);
    return (h ^ bits) * 0x9e3779b97f4a7c15ULL;
}

struct Samples {
    std::vector<glm::dvec3> upper, lower;  // lower: mirrored to the upper hemisphere
    std::string problem;
};

Samples draw(const GltfBxdf& bxdf, const glm::vec3& wo, uint64_t seed) {
    TestRng rng(seed);
    Samples s;
    for (int n = 0; n < kSamples && s.problem.empty(); ++n) {
        const glm::vec2 u = rng.u2();
        const auto sample = bxdf.sample(wo, u, rng.u());
        if (!sample) continue;
        // Pointwise: every sample lies where pdf() is positive, below the surface only for a
        // BSDF that transmits.
        if (!(bxdf.pdf(wo, sample->wi) > 0.0f)) s.problem = "a sample where pdf() is 0 at " + describe(sample->wi);
        if (sample->wi.z < 0.0f && !bxdf.transmits()) s.problem = "a sample below a BSDF that does not transmit";
        if (sample->wi.z > 0.0f) s.upper.push_back(glm::dvec3(sample->wi));
        else s.lower.push_back(glm::dvec3(mirror(sample->wi)));
    }
    return s;
}

ChiSquareOutcome test(const DirectionDomain& domain, const GltfBxdf& bxdf, const glm::vec3& wo, const Samples& s) {
    const size_t cells = size_t(kResolution) * kResolution;
    std::vector<double> observed(2 * cells, 0.0);
    const auto bin = [&](const std::vector<glm::dvec3>& ws, size_t offset) {
        for (const glm::dvec3& w : ws) {
            const glm::dvec2 p = domain.toSquare(w);
            const int x = std::clamp(int(p.x * kResolution), 0, kResolution - 1);
            const int y = std::clamp(int(p.y * kResolution), 0, kResolution - 1);
            observed[offset + size_t(y) * kResolution + x] += 1.0;
        }
    };
    bin(s.upper, 0);
    bin(s.lower, cells);
    std::vector<double> expected = integrateCells(domain, [&](const glm::dvec3& w) {
        return w.z > 0.0 ? double(bxdf.pdf(wo, glm::vec3(w))) : 0.0;
    }, kResolution, 3, 3);
    if (bxdf.transmits()) {
        const std::vector<double> below = integrateCells(domain, [&](const glm::dvec3& w) {
            return w.z > 0.0 ? double(bxdf.pdf(wo, mirror(glm::vec3(w)))) : 0.0;
        }, kResolution, 3, 3);
        expected.insert(expected.end(), below.begin(), below.end());
    } else {
        expected.resize(2 * cells, 0.0);
        observed.resize(cells);
        expected.resize(cells);
    }
    for (double& e : expected) e *= kSamples;
    return chiSquareTest(observed, expected, kSignificance);
}

TEST(GltfChiSquare, SampleFollowsPdf) {
    const std::vector<Case> all = cases();
    for (size_t i = 0; i < all.size(); ++i) {
        const Case& c = all[i];
        const GltfBxdf bxdf(toInputs(c.m));
        for (double degrees : kThetaDegrees) {
            const glm::vec3 wo = toFloatUnit(spherical(degrees * gltfref::kPi / 180.0, 0.7));
            const Samples s = draw(bxdf, wo, caseSeed(i, degrees));
            ASSERT_TRUE(s.problem.empty()) << c.name << " theta " << degrees << ": " << s.problem;
            if (bxdf.transmits()) {
                EXPECT_GT(s.lower.size(), size_t(kSamples / 50)) << c.name;
            }
            const double scale = 1.0 / sharpestAlpha(c.m);
            const auto half = halfVectorDomain(glm::dvec3(wo), scale, scale);
            const auto r = test(*half, bxdf, wo, s);
            EXPECT_TRUE(r.passed) << c.name << " theta " << degrees << " (half-vector domain): " << r.message;
            if (sphericalToo(c.m)) {
                const auto r2 = test(*sphericalDomain(), bxdf, wo, s);
                EXPECT_TRUE(r2.passed) << c.name << " theta " << degrees << " (spherical domain): " << r2.message;
            }
        }
    }
}

// The test must be able to fail: samples of a slightly different material are rejected, both a
// lobe 10 % wider and a transmission that sends 10 % more samples below the surface.
TEST(GltfChiSquare, RejectsAWrongSampler) {
    const glm::vec3 wo = toFloatUnit(spherical(0.8, 0.7));
    Material truth;
    truth.metallic = 1.0;
    truth.roughness = 0.3;
    Material wider = truth;
    wider.roughness = 0.3 * std::sqrt(1.1);
    const GltfBxdf metal(toInputs(truth));
    const auto half = halfVectorDomain(glm::dvec3(wo), 1.0 / 0.09, 1.0 / 0.09);
    EXPECT_FALSE(test(*half, metal, wo, draw(GltfBxdf(toInputs(wider)), wo, 11)).passed);

    truth.metallic = 0.0;
    truth.transmission = 0.5;
    Material more = truth;
    more.transmission = 0.55;
    const GltfBxdf glass(toInputs(truth));
    EXPECT_FALSE(test(*sphericalDomain(), glass, wo, draw(GltfBxdf(toInputs(more)), wo, 12)).passed);
}

}  // namespace
}  // namespace woven
