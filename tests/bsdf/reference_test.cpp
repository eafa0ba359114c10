// GltfBxdf::eval against the independent double-precision reference of reference_gltf_brdf.h,
// for random materials over every feature and direction pairs spread over the hemisphere, at the
// GGX and clearcoat peaks, at grazing angles, and through the thin-walled transmission.
//
// Tolerance. The code works in float (unit roundoff eps = 2^-24 = 6e-8): each factor of f
// (Fresnel, V, D, the layer scales) carries a relative error of a few eps, about 30 eps over the
// ~20 operations of a lobe. One input is badly conditioned: D near its peak. The code forms
// the half vector h in float, so sin^2(theta_h) carries an absolute error of about
// 2 |sin theta_h| eps, and D = a^2 / (pi (a^2 cos^2 + sin^2)^2) moves by a relative
// 4 |sin| eps / (a^2 cos^2 + sin^2) <= 2 eps / alpha (largest at sin = alpha). The Charlie
// distribution sin^(1/alpha_s) likewise multiplies the relative error of sin^2 by 1 / (2 alpha_s).
// And the Fresnel factors: the code takes V.H as |V + L| / 2, exact for unit vectors, but float
// directions are unit only to |w|^2 - 1 ~ 3 eps, and then V.H and |V + L| / 2 differ by up to
// 3 eps / |V + L|, which grazing, nearly opposite pairs amplify: F' <= 5, so F moves by up to
// 15 eps / |V + L|.
// Hence the bound, relative to the size of the terms (termSize: their sum without colours and
// Fresnel weights, so that a difference 1 - F near 0 does not make the tolerance vanish):
//     |f_code - f_ref| <= eps (64 (1 + 2 / alpha + 2 / alpha_coat + 1 / (2 alpha_sheen)) + 16 / |V + L|) size
// about 3 times the worst case observed over all the queries below (the ratio is printed).
// That is a few 1e-4 of f for common roughnesses: any one parameter off by 1 % already shows
// (TellsApartParametersOffByOnePercent), and a wrong formula (a missing pi, a swapped cosine,
// alpha for alpha^2, a Fresnel at the wrong angle) moves f by far more.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_test_util.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr double kEps = 0x1p-24;

// A direction pair for material m, from one of several families.
struct Pair {
    glm::dvec3 wo, wi;
    const char* kind;
};

glm::dvec3 reflectAbout(const glm::dvec3& wo, const glm::dvec3& h) { return 2.0 * glm::dot(wo, h) * h - wo; }

// A normal near n, spread like a GGX lobe of the given alpha (slopes of about alpha).
glm::dvec3 nearNormal(TestRng& rng, const glm::dvec3& n, double alpha) {
    const double r = alpha * std::sqrt(-2.0 * std::log(std::max(1e-300, rng.uniform(0.0, 1.0))));
    const double phi = rng.uniform(0.0, 2.0 * gltfref::kPi);
    glm::dvec3 t = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    t = glm::normalize(t - glm::dot(t, n) * n);
    const glm::dvec3 b = glm::cross(n, t);
    return glm::normalize(n + r * (std::cos(phi) * t + std::sin(phi) * b));
}

Pair randomPair(TestRng& rng, const Material& m) {
    for (;;) {
        glm::dvec3 wo = rng.hemisphere();
        if (rng.chance(0.1)) wo = spherical(rng.uniform(1.45, 1.5706), rng.uniform(0.0, 6.28));  // grazing
        const int kind = int(rng.uniform(0.0, 5.0));
        glm::dvec3 wi;
        const char* name = "";
        switch (kind) {
            case 0: wi = rng.hemisphere(); name = "uniform"; break;
            case 1: wi = reflectAbout(wo, nearNormal(rng, {0, 0, 1}, gltfref::alphaOf(m.roughness))); name = "GGX peak"; break;
            case 2:
                wi = reflectAbout(wo, nearNormal(rng, glm::normalize(m.clearcoatNormal), gltfref::alphaOf(m.clearcoatRoughness)));
                name = "coat peak";
                break;
            case 3: wi = spherical(rng.uniform(1.45, 1.5706), rng.uniform(0.0, 6.28)); name = "grazing"; break;
            default: wi = wo; name = "wi = wo"; break;
        }
        if (wi.z <= 1e-6 || wo.z <= 1e-6) continue;
        if ((m.transmission > 0.0 || m.diffuseTransmission > 0.0) && rng.chance(0.4)) {
            wi = mirror(wi);
            name = "transmission";
        }
        return {wo, wi, name};
    }
}

double tolerance(const Material& m, const glm::vec3& wo, const glm::vec3& wi) {
    const double sheenTerm = gltfref::maxComponent(m.sheenColor) > 0.0 ? 1.0 / (2.0 * gltfref::sheenAlphaOf(m.sheenRoughness)) : 0.0;
    const double coatTerm = m.clearcoat > 0.0 ? 2.0 / gltfref::alphaOf(m.clearcoatRoughness) : 0.0;
    const double halfLength = glm::length(glm::dvec3(wo) + glm::dvec3(mirrorBelow(wi)));
    return kEps * (64.0 * (1.0 + 2.0 / gltfref::alphaOf(m.roughness) + coatTerm + sheenTerm) + 16.0 / halfLength);
}

TEST(GltfReference, EvalMatchesTheSpecification) {
    TestRng rng(20240601);
    constexpr int kMaterials = 400, kPairs = 250;
    double worstRatio = 0.0;
    int failures = 0;
    for (int i = 0; i < kMaterials && failures < 10; ++i) {
        const Material m = randomMaterial(rng);
        const GltfBxdf bxdf(toInputs(m));
        for (int j = 0; j < kPairs && failures < 10; ++j) {
            const Pair p = randomPair(rng, m);
            const glm::vec3 wo = toFloatUnit(p.wo), wi = toFloatUnit(p.wi);
            const glm::dvec3 ref = gltfref::eval(m, glm::dvec3(wo), glm::dvec3(wi), codeSheenAlbedo);
            const glm::dvec3 got(bxdf.eval(wo, wi));
            const double size = termSize(m, glm::dvec3(wo), glm::dvec3(wi));
            const double tol = tolerance(m, wo, wi);
            for (int c = 0; c < 3; ++c) {
                const double ratio = std::abs(got[c] - ref[c]) / (tol * size);
                worstRatio = std::max(worstRatio, ratio);
                if (!(ratio <= 1.0)) {
                    ++failures;
                    ADD_FAILURE() << p.kind << " channel " << c << ": code " << got[c] << " reference " << ref[c]
                                  << " (error " << std::abs(got[c] - ref[c]) / size << " of the terms' size, bound "
                                  << tol << ") wo " << describe(wo) << " wi " << describe(wi) << "\n  " << describe(m);
                    break;
                }
            }
        }
    }
    std::printf("[ reference ] worst error / bound over %d queries: %.3f\n", kMaterials * kPairs, worstRatio);
}

// The comparison must be able to fail: the reference with one parameter off by 1 % (an error
// the size of a wrong constant or a float-rounded table) is told apart from the code.
TEST(GltfReference, TellsApartParametersOffByOnePercent) {
    Material m;
    m.baseColor = {0.8, 0.5, 0.3};
    m.metallic = 0.3;
    m.roughness = 0.4;
    m.anisotropy = 0.5;
    m.ior = 1.45;
    m.specular = 0.9;
    m.transmission = 0.5;
    m.transmittance = {0.9, 0.8, 0.7};
    m.diffuseTransmission = 0.4;
    m.diffuseTransmissionColor = {0.7, 0.6, 0.5};
    m.sheenColor = {0.5, 0.4, 0.3};
    m.sheenRoughness = 0.5;
    m.clearcoat = 0.6;
    m.clearcoatRoughness = 0.2;
    m.clearcoatNormal = glm::normalize(glm::dvec3(0.1, -0.2, 1.0));
    const GltfBxdf bxdf(toInputs(m));
    const std::pair<const char*, void (*)(Material&)> mutations[] = {
        {"base colour", [](Material& x) { x.baseColor *= 1.01; }},
        {"metallic", [](Material& x) { x.metallic *= 1.01; }},
        {"roughness", [](Material& x) { x.roughness *= 1.01; }},
        {"anisotropy", [](Material& x) { x.anisotropy *= 1.01; }},
        {"ior", [](Material& x) { x.ior *= 1.01; }},
        {"specular", [](Material& x) { x.specular *= 1.01; }},
        {"transmission", [](Material& x) { x.transmission *= 1.01; }},
        {"transmittance", [](Material& x) { x.transmittance *= 1.01; }},
        {"diffuse transmission", [](Material& x) { x.diffuseTransmission *= 1.01; }},
        {"diffuse transmission colour", [](Material& x) { x.diffuseTransmissionColor *= 1.01; }},
        {"sheen colour", [](Material& x) { x.sheenColor *= 1.01; }},
        {"sheen roughness", [](Material& x) { x.sheenRoughness *= 1.01; }},
        {"clearcoat", [](Material& x) { x.clearcoat *= 1.01; }},
        {"clearcoat roughness", [](Material& x) { x.clearcoatRoughness *= 1.01; }},
        {"clearcoat normal", [](Material& x) { x.clearcoatNormal = glm::normalize(x.clearcoatNormal + glm::dvec3(0.01, 0, 0)); }},
    };
    for (const auto& [name, mutate] : mutations) {
        Material wrong = m;
        mutate(wrong);
        TestRng rng(5);
        double worst = 0.0;
        for (int j = 0; j < 400; ++j) {
            const Pair p = randomPair(rng, m);
            const glm::vec3 wo = toFloatUnit(p.wo), wi = toFloatUnit(p.wi);
            const glm::dvec3 ref = gltfref::eval(wrong, glm::dvec3(wo), glm::dvec3(wi), codeSheenAlbedo);
            const glm::dvec3 got(bxdf.eval(wo, wi));
            const double bound = tolerance(m, wo, wi) * termSize(m, glm::dvec3(wo), glm::dvec3(wi));
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(got[c] - ref[c]) / bound);
        }
        EXPECT_GT(worst, 2.0) << name << " off by 1 % is not seen";
    }
}

}  // namespace
}  // namespace woven
