// sample(), eval() and pdf() of GltfBxdf agree with one another:
//  - a sample's f and pdf are eval() and pdf() at its direction, and its weight is f |cos| / pdf;
//  - pdf() integrates over the sphere (both hemispheres) to the fraction of sample() calls that
//    return a direction: 1 less the GGX reflections that fall below the horizon and are
//    rejected, so < 1 for rough lobes and grazing views, and never more than 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_test_util.h"
#include "direction_domain.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

glm::vec3 randomView(TestRng& rng) {
    if (rng.chance(0.2)) return toFloatUnit(spherical(rng.uniform(1.45, 1.5705), rng.uniform(0.0, 6.28)));  // grazing
    return toFloatUnit(rng.hemisphere() + glm::dvec3(0.0, 0.0, 1e-6));
}

// KHR_materials_specular's specularFactor 0 leaves a Lambertian surface (the walls of
// bench/render/lambert_box.py): every sample is the cosine lobe's and carries the base colour,
// none is spent on a specular lobe that reflects nothing (which took 2 % of them, 8 % on a red
// wall, each ending its path), and pdf() is the cosine's alone.
TEST(GltfPdf, ALambertianSurfaceSpendsNoSampleOnItsEmptySpecularLobe) {
    Material m;
    m.baseColor = glm::dvec3(0.8, 0.1, 0.1);
    m.metallic = 0.0;
    m.roughness = 1.0;
    m.specular = 0.0;
    const GltfBxdf bxdf(toInputs(m));
    TestRng rng(7);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 wo = randomView(rng);
        const auto s = bxdf.sample(wo, rng.u2(), rng.u());
        ASSERT_TRUE(s) << "wo " << describe(wo);
        ASSERT_NEAR(bxdf.pdf(wo, s->wi), s->wi.z / 3.14159265f, 1e-6f);
        ASSERT_NEAR(glm::length(s->weight - glm::vec3(0.8f, 0.1f, 0.1f)), 0.0f, 1e-5f) << "wo " << describe(wo);
    }
}

TEST(GltfPdf, SampleAgreesWithEvalAndPdf) {
    // sample() computes f and pdf by calling eval() and pdf() on the direction it returns: they
    // must be the same numbers (a relative 1e-6 leaves room for a compiler evaluating an inlined
    // copy in another order); the weight is one division and one product on top.
    TestRng rng(99);
    int failures = 0, samples = 0;
    for (int i = 0; i < 400 && failures < 10; ++i) {
        const Material m = randomMaterial(rng);
        const GltfBxdf bxdf(toInputs(m));
        for (int j = 0; j < 50 && failures < 10; ++j) {
            const glm::vec3 wo = randomView(rng);
            const auto s = bxdf.sample(wo, rng.u2(), rng.u());
            if (!s) continue;
            ++samples;
            const glm::vec3 f = bxdf.eval(wo, s->wi);
            const float pdf = bxdf.pdf(wo, s->wi);
            const glm::vec3 weight = f * (std::abs(s->wi.z) / pdf);
            const auto near = [](const glm::vec3& a, const glm::vec3& b) {
                return glm::all(glm::lessThanEqual(glm::abs(a - b), 1e-6f * glm::max(glm::abs(a), glm::abs(b)) + 1e-30f));
            };
            const bool ok = near(s->f, f) && std::abs(s->pdf - pdf) <= 1e-6f * pdf && near(s->weight, weight) &&
                            std::abs(glm::length(s->wi) - 1.0f) < 1e-5f;
            if (!ok) {
                ++failures;
                ADD_FAILURE() << "sample f " << describe(s->f) << " eval " << describe(f) << ", pdf " << s->pdf
                              << " pdf() " << pdf << ", weight " << describe(s->weight) << " f cos / pdf "
                              << describe(weight) << " wo " << describe(wo) << " wi " << describe(s->wi) << "\n  "
                              << describe(m);
            }
        }
    }
    EXPECT_GT(samples, 15000);
}

TEST(GltfPdf, NoLobeOfProbabilityZeroIsSampled) {
    // The lobes share [0, 1) of uc by their probabilities; rounding can leave their running sum
    // a hair under 1, and a uc in that gap must still go to a lobe pdf() counts. Without sheen
    // or clearcoat, the last lobe that can be chosen has a probability of at least ~0.005, so
    // uc = 1 - 2^-24 and uc = 1 - 2^-12 pick the same lobe, and with the same u the same wi.
    TestRng rng(321);
    int compared = 0, differing = 0;
    for (int i = 0; i < 20000; ++i) {
        Material m = randomMaterial(rng);
        m.sheenColor = glm::dvec3(0.0);
        m.clearcoat = 0.0;
        const GltfBxdf bxdf(toInputs(m));
        const glm::vec3 wo = randomView(rng);
        const glm::vec2 u = rng.u2();
        const auto top = bxdf.sample(wo, u, 0x1.fffffep-1f), below = bxdf.sample(wo, u, 1.0f - 0x1p-12f);
        if (!top || !below) continue;
        ++compared;
        if (top->wi != below->wi && ++differing <= 5)
            ADD_FAILURE() << "uc = 1 - 2^-24 sampled " << describe(top->wi) << ", uc = 1 - 2^-12 " << describe(below->wi)
                          << " at wo " << describe(wo) << "\n  " << describe(m);
    }
    EXPECT_EQ(differing, 0) << "of " << compared;
}

// Integral of pdf(wo, .) over the upper hemisphere and over the lower one (by its mirror image),
// over the half-vector domain of the sharpest lobe, as the chi-square test bins them.
struct PdfMass {
    double upper, lower;
};
PdfMass pdfMass(const GltfBxdf& bxdf, const Material& m, const glm::vec3& wo) {
    double alpha = gltfref::alphaOf(m.roughness);
    if (m.clearcoat > 0.0) alpha = std::min(alpha, gltfref::alphaOf(m.clearcoatRoughness));
    const auto domain = halfVectorDomain(glm::dvec3(wo), 1.0 / alpha, 1.0 / alpha);
    PdfMass mass;
    mass.upper = integrateDomain(*domain, [&](const glm::dvec3& w) {
        return w.z > 0.0 ? double(bxdf.pdf(wo, glm::vec3(w))) : 0.0;
    }, 24, 3);
    mass.lower = bxdf.transmits() ? integrateDomain(*domain, [&](const glm::dvec3& w) {
        return w.z > 0.0 ? double(bxdf.pdf(wo, mirror(glm::vec3(w)))) : 0.0;
    }, 24, 3) : 0.0;
    return mass;
}

TEST(GltfPdf, IntegratesToTheFractionOfSamplesReturned) {
    // The accepted fraction p of N = 4e4 calls has a binomial standard error sqrt(p (1 - p) / N)
    // <= 2.5e-3: |integral - p| <= 4 sigma + 2e-3, the 2e-3 for the quadrature where the horizon
    // cuts the half-vector domain's cells (DomainsCoverTheHemisphere in tests/model: 1e-3).
    // The integral may not exceed 1 + 2e-3. Rough lobes at grazing views lose the most.
    struct Case {
        const char* name;
        Material m;
    };
    std::vector<Case> all;
    Material base;
    base.baseColor = {0.6, 0.5, 0.4};
    base.metallic = 0.0;
    Material m = base;
    m.roughness = 1.0;
    m.specular = 0.0;
    all.push_back({"Lambert (specular 0)", m});
    m = base;
    m.roughness = 0.5;
    all.push_back({"dielectric", m});
    m.metallic = 1.0;
    m.roughness = 1.0;
    all.push_back({"rough metal", m});
    m.roughness = 0.05;
    all.push_back({"smooth metal", m});
    m = base;
    m.roughness = 0.4;
    m.diffuseTransmission = 0.6;
    m.diffuseTransmissionColor = {0.9, 0.3, 0.2};
    all.push_back({"diffuse transmission", m});
    m = base;
    m.roughness = 0.7;
    m.transmission = 1.0;
    all.push_back({"rough thin glass", m});
    m.transmission = 0.5;
    m.diffuseTransmission = 0.5;
    m.sheenColor = {0.8, 0.8, 0.8};
    m.sheenRoughness = 0.4;
    m.clearcoat = 1.0;
    m.clearcoatRoughness = 0.3;
    m.clearcoatNormal = glm::normalize(glm::dvec3(-0.2, 0.3, 1.0));
    all.push_back({"everything, tilted coat", m});
    std::printf("[ pdf mass ] %-26s %8s %8s %8s %8s\n", "material", "theta", "upper", "lower", "returned");
    uint64_t seed = 600;
    for (const Case& c : all) {
        const GltfBxdf bxdf(toInputs(c.m));
        for (double degrees : {0.0, 60.0, 85.0}) {
            const glm::vec3 wo = toFloatUnit(spherical(degrees * gltfref::kPi / 180.0, 0.4));
            const PdfMass mass = pdfMass(bxdf, c.m, wo);
            TestRng rng(++seed);
            constexpr int kDraws = 40000;
            int returned = 0;
            for (int n = 0; n < kDraws; ++n) returned += bxdf.sample(wo, rng.u2(), rng.u()).has_value();
            const double p = double(returned) / kDraws, sigma = std::sqrt(p * (1.0 - p) / kDraws);
            const double total = mass.upper + mass.lower;
            std::printf("[ pdf mass ] %-26s %8.0f %8.4f %8.4f %8.4f\n", c.name, degrees, mass.upper, mass.lower, p);
            EXPECT_LE(total, 1.0 + 2e-3) << c.name << " at " << degrees << " deg";
            EXPECT_NEAR(total, p, 4.0 * sigma + 2e-3) << c.name << " at " << degrees << " deg";
        }
    }
}

}  // namespace
}  // namespace woven
