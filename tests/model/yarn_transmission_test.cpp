// Light through the yarns (docs/MODEL_TRANSMISSION.md): the furnace, the bound R + T <= 1,
// reciprocity, the sampler's chi-square over both hemispheres, no NaN at grazing angles, a
// material of transmission 0 keeping exactly the reflecting lobe of before, and a point's
// transmission being one reciprocal function whichever face sees it.
//
// Quadrature: each hemisphere over the half-vector domain of direction_domain.h (the lower one
// mirrored up, where the glossy transmission has the reflection's shape), whose error on these
// lobes energy_test.cpp bounds by 2e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "direction_domain.h"
#include "reference_brdf.h"
#include "sampling.h"
#include "transmitting_yarn.h"
#include "woven_material.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr double kQuadratureError = 2e-3;
glm::dvec3 mirrored(const glm::dvec3& w) { return {w.x, w.y, -w.z}; }
// The half-vector domain also reaches directions below the horizon (where a reflection is 0):
// each hemisphere's integrand keeps to its own.
double above(const glm::dvec3& w, double value) { return w.z > 0.0 ? value : 0.0; }

struct Shape { float ex, ey; };
const Shape kShapes[] = {{0, 0}, {10, 10}, {100, 2}, {2, 100}, {1e3f, 1e3f}, {1e4f, 1}};
const double kThetas[] = {0.02, 0.785, 1.4835, 1.553};  // 1, 45, 85 and 89 degrees

TransmittingYarn yarn(const Shape& s, float rs, const glm::vec3& rd, float t, float gloss) {
    const LobeShape shape(s.ex, s.ey, rs);
    return TransmittingYarn(AshikhminShirley(shape, rd), YarnTransmission(shape, yarnTransmittance(rd, t), gloss));
}

// The reflected and the transmitted albedo of channel 0 for wo.
struct Albedo { double r, t; };
Albedo albedo(const TransmittingYarn& b, const Shape& s, const glm::vec3& wo) {
    const auto domain = halfVectorDomain(glm::dvec3(wo), std::sqrt(s.ex + 1.0), std::sqrt(s.ey + 1.0));
    const auto r = [&](const glm::dvec3& w) { return above(w, double(b.eval(wo, glm::vec3(w)).x) * w.z); };
    const auto t = [&](const glm::dvec3& w) { return above(w, double(b.eval(wo, glm::vec3(mirrored(w))).x) * w.z); };
    // 32 x 32 cells, each refined until its quarters agree to 1e-4: test_energy's bound holds.
    return {integrateDomain(*domain, r, 32), integrateDomain(*domain, t, 32)};
}

TEST(YarnTransmission, FurnaceAGreyYarnPassingAllItDoesNotReflectLosesNothingInItsBody) {
    // R_d = 0.5 and t = 1 give T = 0.5: the body returns or passes everything that enters, so
    // R + T is the reflection-only albedo at R_d = 1, and the diffuse transmission's albedo is
    // T (1 - R_s) E(mu_o) exactly (its 28 / 23 pi normalisation).
    for (const Shape& s : kShapes)
        for (float rs : {0.0f, 0.04f})
            for (double theta : kThetas) {
                const glm::vec3 wo = sphericalDirection(theta, 0.3);
                const Albedo grey = albedo(yarn(s, rs, glm::vec3(0.5f), 1.0f, 0.0f), s, wo);
                const Albedo white = albedo(yarn(s, rs, glm::vec3(1.0f), 0.0f, 0.0f), s, wo);
                const double coat = 1.0 - std::pow(1.0 - 0.5 * wo.z, 5.0);
                EXPECT_NEAR(grey.r + grey.t, white.r, kQuadratureError) << s.ex << "," << s.ey << " rs " << rs << " theta " << theta;
                EXPECT_NEAR(grey.t, 0.5 * (1.0 - rs) * coat, kQuadratureError) << s.ex << "," << s.ey << " theta " << theta;
                EXPECT_EQ(white.t, 0.0);
            }
}

TEST(YarnTransmission, ReflectedPlusTransmittedAtMostOne) {
    // A grey yarn at t = 1 has R_d + T = 1, the most any colour reaches, and R + T is linear in
    // the gloss g: its ends bound every value between.
    for (const Shape& s : kShapes)
        for (float rs : {0.0f, 0.5f, 1.0f})
            for (float rd : {0.2f, 0.7f})
                for (float gloss : {0.0f, 1.0f})
                    for (double theta : kThetas) {
                        const glm::vec3 wo = sphericalDirection(theta, 1.1);
                        const Albedo a = albedo(yarn(s, rs, glm::vec3(rd), 1.0f, gloss), s, wo);
                        EXPECT_LE(a.r + a.t, 1.0 + kQuadratureError)
                            << s.ex << "," << s.ey << " rs " << rs << " rd " << rd << " g " << gloss << " theta " << theta;
                    }
}

TEST(YarnTransmission, TransmittanceIsTheYarnsHueDeepenedAndLeavesRoomForItsReflection) {
    const glm::vec3 red(0.55f, 0.12f, 0.10f);
    const glm::vec3 t = yarnTransmittance(red, 1.0f);
    EXPECT_FLOAT_EQ(t.r, 0.45f);
    EXPECT_NEAR(t.g, 0.88 * std::pow(0.12 / 0.55, 2.0), 1e-6);
    for (int c = 0; c < 3; ++c) EXPECT_LE(red[c] + t[c], 1.0f);
    EXPECT_EQ(yarnTransmittance(glm::vec3(1.0f), 1.0f), glm::vec3(0.0f));  // white reflects all that enters
    EXPECT_EQ(yarnTransmittance(glm::vec3(0.0f), 1.0f), glm::vec3(0.0f));  // black dye absorbs it
}

TEST(YarnTransmission, Reciprocal) {
    std::mt19937_64 gen(25);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const auto direction = [&](float side) {
        glm::vec3 w = sampleUniformSphere({u01(gen), u01(gen)});
        w.z = side * std::fabs(w.z);
        return w;
    };
    for (const Shape& s : kShapes)
        for (float gloss : {0.0f, 0.5f, 1.0f}) {
            const TransmittingYarn b = yarn(s, 0.04f, glm::vec3(0.4f, 0.3f, 0.2f), 0.8f, gloss);
            for (int n = 0; n < 2000; ++n) {
                const glm::vec3 wo = direction(1.0f), wi = direction(-1.0f);
                const float a = b.eval(wo, wi).x, c = b.eval(wi, wo).x;
                // float rounding of the same terms summed in another order
                EXPECT_NEAR(a, c, 1e-5f * std::max(1.0f, a)) << s.ex << "," << s.ey << " g " << gloss;
                if (gloss < 1.0f) {
                    EXPECT_GT(a, 0.0f);  // the diffuse part reaches every pair
                }
            }
        }
}

// Sidak's correction over the cases of the chi-square test below, as sampling_chi_square_test.cpp.
constexpr int kChiCases = int(std::size(kShapes)) * int(std::size(kThetas)) * 2;
const double kSignificance = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiCases);
constexpr int kSamples = 200000, kResolution = 32;

TEST(YarnTransmission, SamplerMatchesItsDensityOverBothHemispheres) {
    // Both hemispheres' histograms (the lower mirrored up) in one Pearson test, so the choice
    // between reflection and transmission is tested with each lobe's shape.
    int seed = 0;
    for (const Shape& s : kShapes)
        for (double theta : kThetas)
            for (float gloss : {0.0f, 0.7f}) {
                const TransmittingYarn b = yarn(s, 0.04f, glm::vec3(0.5f, 0.4f, 0.3f), 0.9f, gloss);
                const glm::vec3 wo = sphericalDirection(theta, 0.3);
                const auto domain = halfVectorDomain(glm::dvec3(wo), std::sqrt(s.ex + 1.0), std::sqrt(s.ey + 1.0));
                const size_t cells = size_t(kResolution) * kResolution;
                std::vector<double> observed(2 * cells, 0.0);
                std::mt19937_64 gen(uint64_t(++seed) * 0x9e3779b97f4a7c15ULL);
                const auto uniform = [&] { return float(gen() >> 40) * 0x1p-24f; };
                bool outside = false;
                for (int n = 0; n < kSamples; ++n) {
                    const float v = uniform(), u = uniform(), uc = uniform();
                    const auto smp = b.sample(wo, {u, v}, uc);
                    if (!smp) continue;
                    outside |= !(b.pdf(wo, smp->wi) > 0.0f);
                    const bool below = smp->wi.z < 0.0f;
                    const glm::dvec2 p = domain->toSquare(below ? mirrored(glm::dvec3(smp->wi)) : glm::dvec3(smp->wi));
                    const int x = std::clamp(int(p.x * kResolution), 0, kResolution - 1);
                    const int y = std::clamp(int(p.y * kResolution), 0, kResolution - 1);
                    observed[(below ? cells : 0) + size_t(y) * kResolution + size_t(x)] += 1.0;
                }
                EXPECT_FALSE(outside) << "a sample where pdf() is 0";
                std::vector<double> expected =
                    integrateCells(*domain, [&](const glm::dvec3& w) { return above(w, double(b.pdf(wo, glm::vec3(w)))); }, kResolution);
                const std::vector<double> lower = integrateCells(
                    *domain, [&](const glm::dvec3& w) { return above(w, double(b.pdf(wo, glm::vec3(mirrored(w))))); }, kResolution);
                expected.insert(expected.end(), lower.begin(), lower.end());
                for (double& e : expected) e *= kSamples;
                const auto r = chiSquareTest(observed, expected, kSignificance);
                EXPECT_TRUE(r.passed) << s.ex << "," << s.ey << " theta " << theta << " g " << gloss << ": " << r.message;
            }
}

TEST(YarnTransmission, FiniteAtGrazingAndOppositeDirections) {
    const float tiny[] = {0.0f, 1e-30f, 1e-8f, 1e-4f};
    for (const Shape& s : {Shape{0, 0}, Shape{1e5f, 1e5f}, Shape{1e5f, 10}, Shape{0, 1e4f}})
        for (float gloss : {0.0f, 0.5f, 1.0f}) {
            const TransmittingYarn b = yarn(s, 0.04f, glm::vec3(0.5f), 1.0f, gloss);
            for (float zo : tiny)
                for (float zi : tiny)
                    for (float sign : {1.0f, -1.0f}) {
                        const glm::vec3 wo = glm::normalize(glm::vec3(1.0f, 0.2f, zo + 1e-30f));
                        for (const glm::vec3 wi : {glm::normalize(glm::vec3(-1.0f, -0.2f, -sign * zi)),
                                                   glm::normalize(glm::vec3(1.0f, 0.2f, -zi)), glm::vec3(0, 0, -1)}) {
                            const glm::vec3 f = b.eval(wo, wi);
                            EXPECT_TRUE(std::isfinite(f.x) && f.x >= 0.0f) << s.ex << " " << zo << " " << zi;
                            EXPECT_TRUE(std::isfinite(b.pdf(wo, wi)));
                        }
                        for (float uc : {0.0f, 0.3f, 0.99f}) {
                            const auto smp = b.sample(wo, {0.999f, 0.999f}, uc);
                            if (smp) {
                                EXPECT_TRUE(std::isfinite(smp->weight.x) && std::isfinite(smp->pdf)) << s.ex << " " << zo;
                            }
                        }
                    }
        }
}

TEST(YarnTransmission, OnlyPointsWhoseYarnsBothTransmitGetTheLobe) {
    WovenParams p;
    EXPECT_FALSE(WovenMaterial(p).shade(ShadingInput{})->transmission.has_value());
    p.transmission = 0.5f;
    const auto shading = WovenMaterial(p).shade(ShadingInput{});
    ASSERT_TRUE(shading->transmission.has_value());
    // Warp and weft of one colour: the smaller of the two faces' T is that colour's.
    EXPECT_EQ(shading->transmission->lobe().transmittance(), yarnTransmittance(shading->bsdf.lobe().rd(), 0.5f));
    EXPECT_EQ(shading->transmission->lobe().gloss(), p.transmission_gloss);
    // A yarn type sets its own: here the weft passes nothing while the material's warp does. At a
    // crossing the light goes through both, so only where the warp alone covers does any pass.
    p.yarns.resize(1);
    p.yarns[0].value[kYarnTransmission] = 0.0f;
    p.yarns[0].set[kYarnTransmission] = true;
    p.weft_yarns = {0};
    p.yarn_width = 0.5f;  // the weft covers v in [0.25, 0.75] of each element
    const WovenMaterial m(p);
    ShadingInput in;
    in.uv = {0.5, 0.5};  // plain weave: the weft is on top in element (0, 0)
    ASSERT_EQ(m.shade(in)->yarn, YarnType::Weft);
    EXPECT_FALSE(m.shade(in)->transmission.has_value());
    in.uv = {1.5, 0.5};  // the warp on top, the weft under it
    ASSERT_EQ(m.shade(in)->yarn, YarnType::Warp);
    EXPECT_FALSE(m.shade(in)->transmission.has_value());
    in.uv = {1.5, 0.9};  // the warp alone
    ASSERT_EQ(m.shade(in)->yarn, YarnType::Warp);
    EXPECT_TRUE(m.shade(in)->transmission.has_value());
    in.backSide = true;
    EXPECT_TRUE(m.shade(in)->transmission.has_value());
}

// A satin whose faces differ (warp-faced front in one colour, weft-faced back in another), with
// round yarns so each face's bumped frames differ, and the point's BSDF from either face.
WovenParams twoFacedSatin() {
    WovenParams p;
    p.pattern = {5, 1, 2};
    p.warp_color = {0.7f, 0.6f, 0.2f};
    p.weft_color = {0.2f, 0.3f, 0.6f};
    p.cy = 0.9f;
    p.transmission = 0.9f;
    p.transmission_gloss = 0.6f;
    return p;
}
FramedLobe<TransmittingYarn> pointBsdf(const WovenMaterial& m, const glm::dvec2& uv, bool backSide) {
    ShadingInput in;
    in.uv = uv;
    in.backSide = backSide;
    const auto s = m.shade(in);
    EXPECT_TRUE(s && s->transmission);
    return transmittingYarn(s->bsdf, *s->transmission);
}

TEST(YarnTransmission, APointPassesTheSameLightFromEitherFace) {
    // f(wo, wi) for wo at the front and wi at the back, from the front face's BSDF, equals
    // f(wi, wo) from the back face's: one reciprocal function of the point, which BDPT's light
    // subpaths (evaluating from the light's side) and the path tracer both see.
    const WovenMaterial m(twoFacedSatin());
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    const auto direction = [&](float side) {
        glm::vec3 w = sampleUniformSphere({u01(gen), u01(gen)});
        w.z = side * std::max(std::fabs(w.z), 0.05f);
        return glm::normalize(w);
    };
    int differentFaces = 0, compared = 0;
    for (int k = 0; k < 40; ++k) {
        const glm::dvec2 uv(5.0 * u01(gen), 5.0 * u01(gen));
        ShadingInput in;
        in.uv = uv;
        const YarnType frontYarn = m.shade(in)->yarn;
        in.backSide = true;
        differentFaces += m.shade(in)->yarn != frontYarn;
        const auto front = pointBsdf(m, uv, false), back = pointBsdf(m, uv, true);
        for (int n = 0; n < 50; ++n) {
            const glm::vec3 wo = direction(1.0f), wi = direction(-1.0f);
            // Pairs that a face's bumped normal puts on one side are reflections there, which
            // the integrators never connect across the geometric surface (connects()).
            const auto across = [](const FramedLobe<TransmittingYarn>& f, const glm::vec3& a, const glm::vec3& c) {
                return glm::dot(a, f.shadingNormal()) * glm::dot(c, f.shadingNormal()) < 0.0f;
            };
            if (!across(front, wo, wi) || !across(back, wi, wo)) continue;
            ++compared;
            const glm::vec3 a = front.eval(wo, wi), b = back.eval(wi, wo);
            for (int c = 0; c < 3; ++c)  // the two faces' frames agree to float rounding
                EXPECT_NEAR(a[c], b[c], 1e-4f * std::max(1.0f, a[c])) << "uv " << uv.x << "," << uv.y << " channel " << c;
        }
    }
    EXPECT_GT(differentFaces, 20) << "the faces show the same yarn: the test would prove nothing";
    EXPECT_GT(compared, 1000);
}

TEST(YarnTransmission, ReflectedPlusTransmittedAtMostOneFromEitherFace) {
    // Each face reflects with its own yarn and passes the point's light through the front yarn's
    // frame: R + T by Monte Carlo over the composite's own sampler (the mean of its weights), at
    // most 1 within 4 standard errors. Grey yarns of t = 1 reach R_d + T = 1, the worst case;
    // c_y = 1 tilts the two faces' frames apart the most.
    WovenParams p = twoFacedSatin();
    p.warp_color = p.weft_color = glm::vec3(0.5f);
    p.transmission = 1.0f;
    p.cy = 1.0f;
    for (float gloss : {0.0f, 1.0f}) {
        p.transmission_gloss = gloss;
        const WovenMaterial m(p);
        for (double u : {0.1, 0.3, 0.5, 0.7, 0.9})
            for (bool backSide : {false, true})
                for (double theta : {0.0, 0.8, 1.3, 1.5}) {
                    const auto b = pointBsdf(m, {u, 0.37}, backSide);
                    const glm::vec3 wo = b.frame().toWorld(sphericalDirection(theta, 0.4));
                    std::mt19937_64 gen(11);
                    std::uniform_real_distribution<float> u01(0.0f, 0x1.fffffep-1f);
                    constexpr int kN = 20000;
                    double sum = 0.0, sumSq = 0.0;
                    for (int n = 0; n < kN; ++n) {
                        const auto smp = b.sample(wo, {u01(gen), u01(gen)}, u01(gen));
                        const double w = smp ? smp->weight.x : 0.0;
                        sum += w;
                        sumSq += w * w;
                    }
                    const double mean = sum / kN, se = std::sqrt(std::max(0.0, sumSq / kN - mean * mean) / kN);
                    EXPECT_LE(mean, 1.0 + 4.0 * se) << "g " << gloss << " u " << u << " back " << backSide << " theta " << theta;
                }
    }
}

}  // namespace
}  // namespace woven
