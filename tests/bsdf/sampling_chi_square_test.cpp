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
// Domains. (cos theta, phi) of wi for lobes with alpha >= 0.09 (several cells wide), else the
// slopes of the half vector scaled by 1 / alpha of the sharpest lobe (direction_domain.h's
// halfVectorDomain), where a GGX lobe of alpha = 1e-3 still spans many cells and the diffuse
// and sheen parts spread over the outer ones. The horizon cuts the half-vector domain's cells
// along a curve; those cells are integrated finely (cellIntegrals).
//
// Sizes: 1e5 samples per case over 24 x 24 cells per hemisphere, the cells' integrals by
// direction_domain.h's adaptive Gauss-Legendre (order 3, up to 3 splittings, to 1e-4 relative:
// far under the Poisson noise of any cell, 1 / sqrt(expected), 2 % for a cell expecting 2500).
//
// Significance. Each case uses its own fixed seed; the suite should wrongly fail with
// probability alpha = 1 % if the seeds were drawn afresh: Sidak's alpha_i = 1 - (1 - alpha)^(1/M)
// over the M independent tests (M = 51 here, alpha_i = 2.0e-4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
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
    add("anisotropic dielectric", [](Material& m) { m.roughness = 0.3; m.anisotropy = 0.7; });
    add("anisotropic metal (sharp across)", [](Material& m) { m.metallic = 1.0; m.roughness = 0.05; m.anisotropy = 0.9; });
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
    add("diffuse transmission", [](Material& m) {
        m.diffuseTransmission = 0.7;
        m.diffuseTransmissionColor = {0.8, 0.9, 0.3};
        m.roughness = 0.3;
    });
    add("diffuse transmission 1 (sharp specular)", [](Material& m) { m.diffuseTransmission = 1.0; m.roughness = 0.05; });
    add("diffuse and thin transmission, sheen", [](Material& m) {
        m.transmission = 0.4;
        m.diffuseTransmission = 0.5;
        m.sheenColor = {0.6, 0.6, 0.6};
        m.sheenRoughness = 0.4;
    });
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

// The sharpest GGX lobe of a material along x and along y (anisotropy makes the base rougher
// along x), which set the half-vector domain's scales.
glm::dvec2 sharpestAlpha(const Material& m) {
    glm::dvec2 a(gltfref::anisotropicAlphaOf(m.roughness, m.anisotropy), gltfref::alphaOf(m.roughness));
    if (m.clearcoat > 0.0) a = glm::min(a, glm::dvec2(gltfref::alphaOf(m.clearcoatRoughness)));
    return a;
}
// (cos theta, phi) resolves lobes with alpha >= 0.09 (a few cells wide); sharper ones need the
// half-vector domain.
bool usesSphericalDomain(const Material& m) { return std::min(sharpestAlpha(m).x, sharpestAlpha(m).y) >= 0.09; }

int countTests() { return int(cases().size() * std::size(kThetaDegrees)); }
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / countTests());

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

// A cell of a domain as a domain of its own, for integrating it on a finer grid.
class CellDomain : public DirectionDomain {
public:
    CellDomain(const DirectionDomain& inner, const glm::dvec2& origin, double size)
        : inner_(inner), origin_(origin), size_(size) {}
    glm::dvec2 toSquare(const glm::dvec3& wi) const override { return (inner_.toSquare(wi) - origin_) / size_; }
    bool fromSquare(const glm::dvec2& p, glm::dvec3& wi, double& jacobian) const override {
        if (!inner_.fromSquare(origin_ + p * size_, wi, jacobian)) return false;
        jacobian *= size_ * size_;
        return true;
    }

private:
    const DirectionDomain& inner_;
    glm::dvec2 origin_;
    double size_;
};

// Integrals of g (zero below the horizon) over the cells: direction_domain.h's adaptive rule
// (order 3, up to 3 splittings), except in the cells the horizon cuts (some of a 6 x 6 probe
// grid above it and some not, here or in a neighbouring cell), where a sliver of the support can
// slip between the rule's nodes and a cell that holds samples would expect none: those get
// 6 x 6 subcells of the order-3 rule.
std::vector<double> cellIntegrals(const DirectionDomain& domain, const std::function<double(const glm::dvec3&)>& g) {
    std::vector<double> cells = integrateCells(domain, g, kResolution, 3, 3);
    const double size = 1.0 / kResolution;
    std::vector<int> inside(cells.size(), 0);
    for (int cy = 0; cy < kResolution; ++cy)
        for (int cx = 0; cx < kResolution; ++cx)
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 6; ++j) {
                    glm::dvec3 w;
                    double jacobian;
                    const glm::dvec2 p((cx + (i + 0.5) / 6.0) * size, (cy + (j + 0.5) / 6.0) * size);
                    inside[size_t(cy) * kResolution + cx] += domain.fromSquare(p, w, jacobian) && w.z > 0.0;
                }
    const auto at = [&](int x, int y) {
        return x < 0 || y < 0 || x >= kResolution || y >= kResolution ? -1 : inside[size_t(y) * kResolution + x];
    };
    for (int cy = 0; cy < kResolution; ++cy)
        for (int cx = 0; cx < kResolution; ++cx) {
            const int here = at(cx, cy);
            bool cut = here > 0 && here < 36;
            for (int dy = -1; dy <= 1 && !cut && here == 0; ++dy)
                for (int dx = -1; dx <= 1; ++dx) cut = cut || at(cx + dx, cy + dy) > 0;
            if (!cut) continue;
            const CellDomain cell(domain, {cx * size, cy * size}, size);
            const std::vector<double> sub = integrateCells(cell, g, 6, 0, 3);
            cells[size_t(cy) * kResolution + cx] = std::accumulate(sub.begin(), sub.end(), 0.0);
        }
    return cells;
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
    std::vector<double> expected = cellIntegrals(domain, [&](const glm::dvec3& w) {
        return w.z > 0.0 ? double(bxdf.pdf(wo, glm::vec3(w))) : 0.0;
    });
    if (bxdf.transmits()) {
        const std::vector<double> below = cellIntegrals(domain, [&](const glm::dvec3& w) {
            return w.z > 0.0 ? double(bxdf.pdf(wo, mirror(glm::vec3(w)))) : 0.0;
        });
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
            const glm::dvec2 scale = 1.0 / sharpestAlpha(c.m);
            const auto domain = usesSphericalDomain(c.m) ? sphericalDomain() : halfVectorDomain(glm::dvec3(wo), scale.x, scale.y);
            const auto r = test(*domain, bxdf, wo, s);
            EXPECT_TRUE(r.passed) << c.name << " theta " << degrees << (usesSphericalDomain(c.m) ? " (spherical" : " (half-vector")
                                  << " domain): " << r.message;
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

    // And a diffuse transmission that sends 10 % more of the diffuse samples below.
    Material leaf;
    leaf.metallic = 0.0;
    leaf.roughness = 0.5;
    leaf.diffuseTransmission = 0.5;
    Material brighter = leaf;
    brighter.diffuseTransmission = 0.55;
    const GltfBxdf thin(toInputs(leaf));
    EXPECT_FALSE(test(*sphericalDomain(), thin, wo, draw(GltfBxdf(toInputs(brighter)), wo, 13)).passed);
}

}  // namespace
}  // namespace woven
