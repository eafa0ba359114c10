// Goodness of fit of sample() against pdf() (pbrt-v4 / Mitsuba style): histogram sampled
// directions over the cells of a direction domain, integrate pdf() over each cell numerically,
// Pearson's chi-square with pooling of cells expected below 5 samples.
//
// Significance. Every case is its own test, with a fixed seed; the suite as a whole should
// wrongly fail with probability alpha = 1% if the seeds were drawn afresh, so each of the M
// cases uses Sidak's alpha_i = 1 - (1 - alpha)^(1 / M) (the cases use disjoint random numbers,
// so they are independent and Sidak is exact). M counts all cases in this file.
//
// Domains. The bare lobe is binned (a) over (cos theta, phi) of wi as pbrt does, for lobes no
// sharper than e = 100 (about 0.1 rad wide, several cells), and (b) for every lobe over the half
// vector's slopes scaled by sqrt(e + 1) (direction_domain.h), where a lobe of e = 1e4 or an
// anisotropy of 1e4 still spans about a quarter of the grid in each direction; a (cos theta,
// phi) grid would put such a lobe into one cell and could not see a wrong shape.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <random>
#include <sstream>

#include "ashikhmin_shirley.h"
#include "direction_domain.h"
#include "reference_brdf.h"
#include "woven_material.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr int kSamples = 200000;
constexpr int kResolution = 32;

struct Exponents { float ex, ey; };
const Exponents kExponents[] = {{0, 0},       {1, 1},       {10, 10},  {100, 2},  {2, 100},
                                {1e3f, 1e3f}, {1e4f, 1e4f}, {1, 1e4f}, {1e4f, 1}, {0, 1e4f}};
const double kThetas[] = {0.02, 0.785, 1.4835, 1.553};  // 1, 45, 85 and 89 degrees
constexpr int kSphericalMaxExponent = 100;

struct MaterialPoint { const char* name; glm::dvec2 uv; YarnType yarn; };
const MaterialPoint kMaterialPoints[] = {{"weft", {0.5, 0.5}, YarnType::Weft},
                                         {"warp", {9.5, 0.5}, YarnType::Warp},
                                         {"bumped weft (x = 0.9)", {2.5, 0.95}, YarnType::Weft},
                                         {"bumped warp (x = -0.86)", {9.07, 0.5}, YarnType::Warp}};
const double kMaterialThetas[] = {0.3, 1.45};

int countCases() {
    int spherical = 0;
    for (const auto& e : kExponents) spherical += std::max(e.ex, e.ey) <= kSphericalMaxExponent;
    const int lobe = int(std::size(kExponents)) * int(std::size(kThetas));
    const int material = int(std::size(kMaterialPoints)) * int(std::size(kMaterialThetas));
    return lobe + spherical * int(std::size(kThetas)) + material + 1;  // + 1: pure specular case
}
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / countCases());

float uniform01(std::mt19937_64& gen) { return float(gen() >> 40) * 0x1p-24f; }

// Samples directions in a local frame (std::nullopt where the sampler gives none).
using Sampler = std::function<std::optional<glm::dvec3>(const glm::vec2& u, float uc)>;
using Density = std::function<double(const glm::dvec3& wi)>;

ChiSquareOutcome chiSquare(const DirectionDomain& domain, const Sampler& sample, const Density& pdf, uint64_t seed) {
    std::mt19937_64 gen(seed);
    std::vector<double> observed(size_t(kResolution) * kResolution, 0.0);
    for (int n = 0; n < kSamples; ++n) {
        // One draw at a time (a call's arguments are evaluated in an order each compiler
        // chooses), v first: the order the test's thresholds were checked with (GCC's).
        const float v = uniform01(gen), u = uniform01(gen);
        const auto wi = sample({u, v}, uniform01(gen));
        if (!wi) continue;
        // Samples outside the support are caught here, pointwise.
        if (!(pdf(*wi) > 0.0)) return {false, 0.0, 0.0, 0, "a sample where pdf() is 0"};
        const glm::dvec2 p = domain.toSquare(*wi);
        const int x = std::clamp(int(p.x * kResolution), 0, kResolution - 1);
        const int y = std::clamp(int(p.y * kResolution), 0, kResolution - 1);
        observed[size_t(y) * kResolution + x] += 1.0;
    }
    std::vector<double> expected = integrateCells(domain, pdf, kResolution);
    for (double& e : expected) e *= kSamples;
    return chiSquareTest(observed, expected, kSignificance);
}

std::unique_ptr<DirectionDomain> lobeDomain(const glm::dvec3& wo, float ex, float ey) {
    return halfVectorDomain(wo, std::sqrt(ex + 1.0), std::sqrt(ey + 1.0));
}

Sampler lobeSampler(const AshikhminShirley& lobe, const glm::vec3& wo) {
    return [&lobe, wo](const glm::vec2& u, float uc) -> std::optional<glm::dvec3> {
        const auto s = lobe.sample(wo, u, uc);
        if (!s) return std::nullopt;
        return glm::dvec3(s->wi);
    };
}
Density lobeDensity(const AshikhminShirley& lobe, const glm::vec3& wo) {
    return [&lobe, wo](const glm::dvec3& wi) { return double(lobe.pdf(wo, glm::vec3(wi))); };
}

// A seed from the case's own parameters, so a case sees the same numbers however the suite is
// filtered or ordered.
uint64_t caseSeed(int domainKind, double a, double b, double theta) {
    uint64_t h = 0x5eedULL + uint64_t(domainKind);
    for (double v : {a, b, theta}) {
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ULL;
        h ^= h >> 29;
    }
    return h;
}

TEST(ChiSquare, BareLobeHalfVectorDomain) {
    for (const Exponents& e : kExponents)
        for (double theta : kThetas) {
            const AshikhminShirley lobe(e.ex, e.ey, 0.04f, glm::vec3(0.5f, 0.4f, 0.3f));
            const glm::vec3 wo = sphericalDirection(theta, 0.3);
            const auto domain = lobeDomain(glm::dvec3(wo), e.ex, e.ey);
            const auto r = chiSquare(*domain, lobeSampler(lobe, wo), lobeDensity(lobe, wo), caseSeed(0, e.ex, e.ey, theta));
            EXPECT_TRUE(r.passed) << "e=(" << e.ex << "," << e.ey << ") theta=" << theta << ": " << r.message;
        }
}

TEST(ChiSquare, BareLobeSphericalDomain) {
    for (const Exponents& e : kExponents) {
        if (std::max(e.ex, e.ey) > kSphericalMaxExponent) continue;
        for (double theta : kThetas) {
            const AshikhminShirley lobe(e.ex, e.ey, 0.04f, glm::vec3(0.5f, 0.4f, 0.3f));
            const glm::vec3 wo = sphericalDirection(theta, 0.3);
            const auto domain = sphericalDomain();
            const auto r = chiSquare(*domain, lobeSampler(lobe, wo), lobeDensity(lobe, wo), caseSeed(1, e.ex, e.ey, theta));
            EXPECT_TRUE(r.passed) << "e=(" << e.ex << "," << e.ey << ") theta=" << theta << ": " << r.message;
        }
    }
}

TEST(ChiSquare, PureSpecularLobe) {
    // No diffuse term: all samples come from the half-vector sampling.
    const AshikhminShirley lobe(300.0f, 30.0f, 1.0f, glm::vec3(0.0f));
    ASSERT_EQ(lobe.specularProbability(), 1.0f);
    const glm::vec3 wo = sphericalDirection(1.2, 2.0);
    const auto domain = lobeDomain(glm::dvec3(wo), 300.0f, 30.0f);
    const auto r = chiSquare(*domain, lobeSampler(lobe, wo), lobeDensity(lobe, wo), caseSeed(2, 300, 30, 1.2));
    EXPECT_TRUE(r.passed) << r.message;
}

TEST(ChiSquare, WovenMaterialInWorldSpace) {
    WovenParams p;
    p.pattern = {9, 1, 3};  // satin: weft at (0..8, 0), warp at (9, 0)
    p.ex = 300.0f;
    p.ey = 5.0f;
    p.warp_ex = 2000.0f;
    p.warp_ey = 1.0f;
    p.cy = 1.0f;
    p.crimp = 0.5f;
    p.noise = 0.3f;
    p.rs = 0.06f;
    const WovenMaterial material(p);
    ShadingInput in;
    in.ns = glm::normalize(glm::vec3(0.2f, -0.3f, 0.9f));
    in.dpdu = glm::vec3(1.5f, 0.2f, 0.3f);
    in.dpdv = glm::vec3(-0.1f, 0.8f, 0.2f);
    for (const MaterialPoint& point : kMaterialPoints) {
        in.uv = point.uv;
        const auto shading = material.shade(in);
        ASSERT_TRUE(shading.has_value()) << point.name;
        const SurfaceBsdf& bsdf = shading->bsdf;
        const Frame frame = bsdf.frame();
        ASSERT_EQ(shading->yarn, point.yarn) << point.name;
        const bool weft = point.yarn == YarnType::Weft;
        const float ex = weft ? p.ex : p.warp_ex, ey = weft ? p.ey : p.warp_ey;
        for (double theta : kMaterialThetas) {
            const glm::vec3 woLocal = sphericalDirection(theta, 1.0);
            const glm::vec3 wo = frame.toWorld(woLocal);
            const auto domain = lobeDomain(glm::dvec3(woLocal), ex, ey);
            const Sampler sampler = [&](const glm::vec2& u, float uc) -> std::optional<glm::dvec3> {
                const auto s = bsdf.sample(wo, u, uc);
                if (!s) return std::nullopt;
                return glm::dvec3(frame.toLocal(s->wi));
            };
            const Density density = [&](const glm::dvec3& wiLocal) {
                return double(bsdf.pdf(wo, frame.toWorld(glm::vec3(wiLocal))));
            };
            const auto r = chiSquare(*domain, sampler, density, caseSeed(3, point.uv.x, point.uv.y, theta));
            EXPECT_TRUE(r.passed) << point.name << " theta=" << theta << ": " << r.message;
        }
    }
}

// The test itself must be able to fail: a sampler for a slightly different lobe, or one with
// its axes swapped, is rejected.
TEST(ChiSquare, RejectsAWrongSampler) {
    const glm::vec3 wo = sphericalDirection(0.7, 0.3);
    const AshikhminShirley truth(100.0f, 20.0f, 0.04f, glm::vec3(0.5f));
    const AshikhminShirley wider(90.0f, 20.0f, 0.04f, glm::vec3(0.5f));
    const AshikhminShirley swapped(20.0f, 100.0f, 0.04f, glm::vec3(0.5f));
    const AshikhminShirley muchWider(60.0f, 20.0f, 0.04f, glm::vec3(0.5f));
    const auto domain = lobeDomain(glm::dvec3(wo), 100.0f, 20.0f);
    EXPECT_FALSE(chiSquare(*domain, lobeSampler(wider, wo), lobeDensity(truth, wo), 42).passed);
    EXPECT_FALSE(chiSquare(*domain, lobeSampler(swapped, wo), lobeDensity(truth, wo), 43).passed);
    const auto spherical = sphericalDomain();
    // The (cos theta, phi) grid is coarser for this lobe: it needs a larger error to see one.
    EXPECT_FALSE(chiSquare(*spherical, lobeSampler(muchWider, wo), lobeDensity(truth, wo), 44).passed);
}

TEST(ChiSquare, DomainsCoverTheHemisphere) {
    // The tooling: both domains integrate 1 over the upper hemisphere to 2 pi. The horizon cuts
    // the half-vector domain's cells along a curve, where the adaptive rule stops at 1/16 of a
    // cell: a relative 1e-3 there moves the expected counts of 2e5 samples by well under one
    // sample per cell, far below their Poisson noise.
    const auto one = [](const glm::dvec3& wi) { return wi.z > 0.0 ? 1.0 : 0.0; };
    EXPECT_NEAR(integrateDomain(*sphericalDomain(), one), 2.0 * kPi, 1e-9);
    for (double theta : {0.0, 1.0, 1.55})
        for (double scale : {1.0, 100.0}) {
            const auto domain = halfVectorDomain(glm::dvec3(sphericalDirection(theta, 0.4)), scale, scale);
            EXPECT_NEAR(integrateDomain(*domain, one, 32), 2.0 * kPi, 2.0 * kPi * 1e-3) << theta << " " << scale;
        }
    // chiSquarePValue: the median of chi-square with 10 degrees of freedom is 9.342.
    EXPECT_NEAR(chiSquarePValue(9.3418, 10), 0.5, 1e-4);
    EXPECT_NEAR(chiSquarePValue(23.209, 10), 0.01, 1e-4);
}

}  // namespace
}  // namespace woven
