// The Ashikhmin-Shirley lobe against the double-precision reference written from MODEL.md,
// reciprocity, the pdf's integral, and sample()'s returned values.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ashikhmin_shirley.h"
#include "direction_domain.h"
#include "reference_brdf.h"

namespace woven {
namespace {

using namespace woven::test;

struct LobeCase {
    float ex, ey, rs;
    glm::vec3 rd;
};

const LobeCase kLobes[] = {
    {0.0f, 0.0f, 0.04f, {0.5f, 0.3f, 0.2f}}, {1.0f, 1.0f, 0.5f, {0.8f, 0.8f, 0.8f}},
    {100.0f, 2.0f, 0.04f, {0.55f, 0.12f, 0.1f}}, {2.0f, 100.0f, 0.04f, {0.2f, 0.9f, 0.1f}},
    {1e4f, 1e4f, 1.0f, {0.0f, 0.0f, 0.0f}}, {1.0f, 1e4f, 0.1f, {0.3f, 0.3f, 0.3f}},
    {1e4f, 1.0f, 0.0f, {1.0f, 1.0f, 1.0f}}, {1e5f, 10.0f, 0.9f, {0.1f, 0.1f, 0.1f}},
    {0.0f, 1e5f, 0.04f, {0.5f, 0.5f, 0.5f}},
};

float uniform01(std::mt19937_64& gen) { return float(gen() >> 40) * 0x1p-24f; }

glm::vec3 randomHemisphere(std::mt19937_64& gen) {
    const float z = uniform01(gen), phi = 6.2831853f * uniform01(gen);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return glm::normalize(glm::vec3(r * std::cos(phi), r * std::sin(phi), std::max(z, 1e-4f)));
}

// A direction whose half vector with wo lies near the lobe's peak, so sharp lobes are probed
// where they are large, not only where they vanish.
glm::vec3 nearSpecular(const glm::vec3& wo, const LobeCase& c, std::mt19937_64& gen) {
    std::normal_distribution<float> gauss;
    // Drawn one by one, y first: the order of a call's arguments is up to the compiler, and this
    // is the order the test's directions were checked with (GCC's).
    const float y = gauss(gen), x = gauss(gen);
    const glm::vec3 h = glm::normalize(glm::vec3(x / std::sqrt(c.ex + 1.0f), y / std::sqrt(c.ey + 1.0f), 1.0f));
    return glm::normalize(2.0f * glm::dot(wo, h) * h - wo);
}

// A normal random vector, drawn z first, as nearSpecular() draws.
glm::dvec3 jitter(std::normal_distribution<double>& gauss, std::mt19937_64& gen) {
    const double z = gauss(gen), y = gauss(gen), x = gauss(gen);
    return {x, y, z};
}

TEST(AshikhminShirley, EvalMatchesDoublePrecisionReference) {
    std::mt19937_64 gen(12345);
    std::normal_distribution<double> gauss;
    for (const LobeCase& c : kLobes) {
        const AshikhminShirley lobe(c.ex, c.ey, c.rs, c.rd);
        const ReferenceAS ref{c.ex, c.ey, c.rs, glm::dvec3(c.rd)};
        double peak = 0.0;
        for (int n = 0; n < 20000; ++n) {
            const glm::vec3 wo = randomHemisphere(gen);
            const glm::vec3 wi = n % 2 ? randomHemisphere(gen) : nearSpecular(wo, c, gen);
            if (wi.z <= 1e-4f) continue;
            // A float direction stands for any unit direction within about 1e-7 of it. Near
            // h.k -> 0 or with N = 1e5 the BRDF is that sensitive to it, so the reference gives
            // the range over a few such directions and the float result must lie in it, up to a
            // relative 1e-3 for float arithmetic on (n.h)^N.
            glm::dvec3 lo = ref.eval(toDouble(wo), toDouble(wi)), hi = lo;
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 jo = jitter(gauss, gen), ji = jitter(gauss, gen);
                const glm::dvec3 v = ref.eval(toDouble(wo) + 6e-8 * jo, toDouble(wi) + 6e-8 * ji);
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            const glm::vec3 got = lobe.eval(wo, wi);
            peak = std::max(peak, hi.g);
            for (int k = 0; k < 3; ++k) {
                ASSERT_GE(got[k], lo[k] * (1.0 - 1e-3) - 1e-6) << "e=(" << c.ex << "," << c.ey << ") wo=(" << wo.x
                    << "," << wo.y << "," << wo.z << ") wi=(" << wi.x << "," << wi.y << "," << wi.z << ")";
                ASSERT_LE(got[k], hi[k] * (1.0 + 1e-3) + 1e-6) << "e=(" << c.ex << "," << c.ey << ") wo=(" << wo.x
                    << "," << wo.y << "," << wo.z << ") wi=(" << wi.x << "," << wi.y << "," << wi.z << ")";
            }
        }
        EXPECT_GT(peak, 1.0) << "the sweep never reached the specular peak";
    }
}

TEST(AshikhminShirley, AxesAreNotSwapped) {
    // e_x belongs to the x axis: with e_x >> e_y the lobe is narrow along x. A half vector tilted
    // by slope 0.1 along x has (n.h)^1000 = e^-4.98, along y (n.h)^1 = 0.995.
    const AshikhminShirley lobe(1000.0f, 1.0f, 0.5f, glm::vec3(0.0f));
    const glm::vec3 tiltX = glm::normalize(glm::vec3(0.1f, 0.0f, 1.0f));
    const glm::vec3 tiltY = glm::normalize(glm::vec3(0.0f, 0.1f, 1.0f));
    EXPECT_LT(lobe.halfVectorPdf(tiltX), 0.01f * lobe.halfVectorPdf(tiltY));
    const ReferenceAS ref{1000.0, 1.0, 0.5, glm::dvec3(0.0)};
    EXPECT_NEAR(lobe.halfVectorPdf(tiltY), ref.halfVectorPdf(toDouble(tiltY)), 1e-4 * ref.halfVectorPdf(toDouble(tiltY)));
}

TEST(AshikhminShirley, Reciprocity) {
    std::mt19937_64 gen(777);
    for (const LobeCase& c : kLobes) {
        const AshikhminShirley lobe(c.ex, c.ey, c.rs, c.rd);
        for (int n = 0; n < 20000; ++n) {
            const glm::vec3 a = randomHemisphere(gen);
            const glm::vec3 b = n % 2 ? randomHemisphere(gen) : nearSpecular(a, c, gen);
            if (b.z <= 1e-4f) continue;
            const glm::vec3 fab = lobe.eval(a, b), fba = lobe.eval(b, a);
            for (int k = 0; k < 3; ++k) ASSERT_NEAR(fab[k], fba[k], 1e-4f * fab[k] + 1e-7f) << c.ex << "," << c.ey;
        }
    }
}

TEST(AshikhminShirley, HalfVectorPdfIsNormalised) {
    // p_h integrates to 1 over the hemisphere of h (A-S's normalisation, exact for any e_x, e_y):
    // integrate the reference-free code value in the stretched slope domain with wo = n (where
    // h spans the hemisphere as wi does, Jacobian 4 (wo.h) divided out).
    for (const LobeCase& c : kLobes) {
        const AshikhminShirley lobe(c.ex, c.ey, c.rs, c.rd);
        const glm::dvec3 n(0, 0, 1);
        const auto domain = halfVectorDomain(n, std::sqrt(c.ex + 1.0), std::sqrt(c.ey + 1.0));
        const double total = integrateDomain(*domain, [&](const glm::dvec3& wi) {
            const glm::dvec3 h = glm::normalize(wi + n);
            if (!(h.z > 0.0)) return 0.0;  // h on the horizon: measure zero
            return lobe.halfVectorPdf(glm::vec3(h)) / (4.0 * h.z);
        });
        EXPECT_NEAR(total, 1.0, 2e-3) << c.ex << "," << c.ey;
    }
}

// The part of the specular sampling that is lost below the horizon, from the reference p_h:
// the half vectors h whose mirror direction of wo lies below the surface.
double referenceLostFraction(const ReferenceAS& ref, const glm::dvec3& wo) {
    const glm::dvec3 n(0, 0, 1);
    const auto domain = halfVectorDomain(n, std::sqrt(ref.ex + 1.0), std::sqrt(ref.ey + 1.0));
    return integrateDomain(*domain, [&](const glm::dvec3& w) {
        const glm::dvec3 h = glm::normalize(w + n);  // h over its hemisphere
        if (!(h.z > 0.0)) return 0.0;               // h on the horizon: measure zero
        const double oh = glm::dot(wo, h);
        const glm::dvec3 wi = 2.0 * oh * h - wo;
        const bool lost = oh <= 0.0 || wi.z <= 0.0;
        return lost ? ref.halfVectorPdf(h) / (4.0 * h.z) : 0.0;
    }, 32);
}

TEST(AshikhminShirley, PdfIntegratesToOneMinusTheLostPart) {
    const double thetas[] = {0.0, 0.5, 1.2, 1.5, 1.5607};  // down to 0.6 degrees above the horizon
    for (const LobeCase& c : kLobes) {
        const AshikhminShirley lobe(c.ex, c.ey, c.rs, c.rd);
        const ReferenceAS ref{c.ex, c.ey, c.rs, glm::dvec3(c.rd)};
        for (double theta : thetas) {
            const glm::vec3 wo = sphericalDirection(theta, 0.7);
            const auto domain = halfVectorDomain(toDouble(wo), std::sqrt(c.ex + 1.0), std::sqrt(c.ey + 1.0));
            const double total = integrateDomain(*domain, [&](const glm::dvec3& wi) {
                return double(lobe.pdf(wo, glm::vec3(wi)));
            }, 32);
            const double expected = 1.0 - lobe.specularProbability() * referenceLostFraction(ref, toDouble(wo));
            EXPECT_NEAR(total, expected, 3e-3) << "e=(" << c.ex << "," << c.ey << ") theta=" << theta;
            EXPECT_LE(total, 1.0 + 3e-3);
        }
    }
}

TEST(AshikhminShirley, SampleReturnsConsistentValues) {
    std::mt19937_64 gen(99);
    for (const LobeCase& c : kLobes) {
        const AshikhminShirley lobe(c.ex, c.ey, c.rs, c.rd);
        int produced = 0;
        for (int n = 0; n < 20000; ++n) {
            const glm::vec3 wo = randomHemisphere(gen);
            const glm::vec2 u(uniform01(gen), uniform01(gen));
            const auto s = lobe.sample(wo, u, uniform01(gen));
            if (!s) continue;
            ++produced;
            ASSERT_GT(s->wi.z, 0.0f);
            ASSERT_NEAR(glm::length(s->wi), 1.0f, 1e-4f);
            const float pdf = lobe.pdf(wo, s->wi);
            const glm::vec3 f = lobe.eval(wo, s->wi);
            ASSERT_NEAR(s->pdf, pdf, 1e-5f * pdf);
            for (int k = 0; k < 3; ++k) {
                ASSERT_NEAR(s->f[k], f[k], 1e-5f * f[k]);
                const double weight = double(f[k]) * s->wi.z / pdf;
                ASSERT_NEAR(s->weight[k], weight, 1e-4 * weight + 1e-9) << c.ex << "," << c.ey;
            }
        }
        EXPECT_GT(produced, 5000) << c.ex << "," << c.ey;
    }
}

}  // namespace
}  // namespace woven
