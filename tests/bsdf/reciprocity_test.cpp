// Reciprocity of GltfBxdf (Helmholtz): f(wo, wi) = f(wi, wo).
//
// Reflection: both directions are in the upper hemisphere of the same local frame, and swapping
// them must not change f, with every feature on (sheen's min of the two albedo scalings and the
// coat's max of the two Fresnel factors exist for this).
//
// Thin-walled and diffuse transmission: eval() wants wo on the side of the frame's z (GltfMaterial::bsdf
// turns the shading normal to the viewer's side), so light going the other way, from wi's side
// to wo's, is evaluated by the BSDF the material builds on the other side. That frame's z is -n:
// a world direction d has the local coordinates M(d) = (d.x, d.y, -d.z) up to a rotation about
// z, which an isotropic BSDF cannot see; its clearcoat normal is the world coat normal turned
// with it, -N_c, in local coordinates M(-c) = (-c.x, -c.y, c.z). A thin wall has the same medium
// on both sides (no eta^2 factor), so reciprocity reads
//     f[c](wo, wi) = f[M(-c)](M(wi), M(wo))      for wo.z > 0 > wi.z.
//
// Tolerance: the code computes both sides from the same half vector (wo + wi is commutative in
// float), so D and V agree to the last bit and the base's Fresnel (from |wo + wi| / 2) too: a
// few roundoffs of each term, 16 eps of the terms' size (the sum of the lobes' magnitudes, as in
// reference_test.cpp). The coat's Fresnel is taken at wo.h, which the swap turns into wi.h: for
// float directions, unit only to |w|^2 - 1 ~ 3 eps, the two differ by (|wo|^2 - |wi|^2) / |wo + wi|,
// up to 6 eps / |wo + wi|, and F' <= 5 (1 - F0): the coat term may move by 32 eps / |wo + wi|
// of itself, which at grazing, nearly opposite pairs (|wo + wi| ~ 0.02) is 1e-4 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "bsdf_test_util.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

constexpr double kEps = 0x1p-24;

double bound(const Material& m, const glm::vec3& wo, const glm::vec3& wi) {
    const glm::dvec3 v(wo), l(wi), lm = l.z > 0.0 ? l : mirror(l);
    return 16.0 * kEps * termSize(m, v, l) + 32.0 * kEps * coatTermSize(m, v, lm) / glm::length(v + lm);
}

glm::vec3 randomUpper(TestRng& rng) {
    // Mostly uniform, some grazing, some near the normal.
    switch (int(rng.uniform(0.0, 4.0))) {
        case 0: return toFloatUnit(spherical(rng.uniform(1.4, 1.5707), rng.uniform(0.0, 6.2832)));
        case 1: return toFloatUnit(spherical(rng.uniform(0.0, 0.05), rng.uniform(0.0, 6.2832)));
        default: return toFloatUnit(rng.hemisphere() + glm::dvec3(0.0, 0.0, 1e-9));
    }
}

TEST(GltfReciprocity, ReflectionIsSymmetric) {
    TestRng rng(77);
    int failures = 0;
    double worst = 0.0;
    for (int i = 0; i < 500 && failures < 10; ++i) {
        const Material m = randomMaterial(rng);
        const GltfBxdf bxdf(toInputs(m));
        for (int j = 0; j < 200 && failures < 10; ++j) {
            const glm::vec3 wo = randomUpper(rng);
            glm::vec3 wi = randomUpper(rng);
            if (j % 4 == 0) wi = glm::vec3(-wo.x, -wo.y, wo.z);  // the mirror direction, the GGX peak
            const glm::vec3 a = bxdf.eval(wo, wi), b = bxdf.eval(wi, wo);
            const double tol = bound(m, wo, wi);
            for (int c = 0; c < 3; ++c) {
                const double diff = std::abs(double(a[c]) - double(b[c]));
                worst = std::max(worst, diff / tol);
                if (!(diff <= tol)) {
                    ++failures;
                    ADD_FAILURE() << "f(wo, wi) = " << a[c] << ", f(wi, wo) = " << b[c] << " (channel " << c
                                  << ") wo " << describe(wo) << " wi " << describe(wi) << "\n  " << describe(m);
                    break;
                }
            }
        }
    }
    std::printf("[ reciprocity ] reflection: worst difference / bound %.3f\n", worst);
}

// Transmission of random materials that `makeTransmit` makes transmitting, seen from both sides.
void expectTransmissionReciprocal(uint64_t seed, void (*makeTransmit)(TestRng&, Material&), const char* label) {
    TestRng rng(seed);
    int failures = 0, tested = 0;
    double worst = 0.0;
    for (int i = 0; i < 500 && failures < 10; ++i) {
        Material m = randomMaterial(rng);
        m.metallic = std::min(m.metallic, 0.9);
        makeTransmit(rng, m);
        if (i % 2 == 0) {  // half of them with a clearcoat, tilted as a coat normal map would
            m.clearcoat = rng.uniform(0.2, 1.0);
            m.clearcoatNormal = glm::normalize(rng.hemisphere() + glm::dvec3(0.0, 0.0, 1.0));
        }
        Material back = m;
        back.clearcoatNormal = {-m.clearcoatNormal.x, -m.clearcoatNormal.y, m.clearcoatNormal.z};
        const GltfBxdf front(toInputs(m)), behind(toInputs(back));
        ASSERT_TRUE(front.transmits());
        for (int j = 0; j < 200 && failures < 10; ++j) {
            const glm::vec3 wo = randomUpper(rng);
            glm::vec3 wi = mirror(randomUpper(rng));
            if (j % 4 == 0) wi = -wo;  // straight through: the transmission peak
            const glm::vec3 a = front.eval(wo, wi), b = behind.eval(mirror(wi), mirror(wo));
            const double tol = bound(m, wo, wi);
            tested += a != glm::vec3(0.0f);
            for (int c = 0; c < 3; ++c) {
                const double diff = std::abs(double(a[c]) - double(b[c]));
                worst = std::max(worst, diff / tol);
                if (!(diff <= tol)) {
                    ++failures;
                    ADD_FAILURE() << "front f(wo, wi) = " << a[c] << ", back f(M wi, M wo) = " << b[c] << " (channel "
                                  << c << ") wo " << describe(wo) << " wi " << describe(wi) << "\n  " << describe(m);
                    break;
                }
            }
        }
    }
    EXPECT_GT(tested, 50000);  // the transmission lobe really was non-zero
    std::printf("[ reciprocity ] %s: worst difference / bound %.3f\n", label, worst);
}

TEST(GltfReciprocity, ThinTransmissionIsSymmetricSeenFromTheOtherSide) {
    expectTransmissionReciprocal(78, [](TestRng& rng, Material& m) { m.transmission = rng.uniform(0.1, 1.0); },
                                 "thin transmission");
}

TEST(GltfReciprocity, DiffuseTransmissionIsSymmetricSeenFromTheOtherSide) {
    expectTransmissionReciprocal(79, [](TestRng& rng, Material& m) {
        m.transmission = rng.chance(0.3) ? rng.uniform(0.0, 0.9) : 0.0;
        m.diffuseTransmission = rng.uniform(0.1, 1.0);
        m.diffuseTransmissionColor = rng.color(0.1, 1.0);
    }, "diffuse transmission");
}

}  // namespace
}  // namespace woven
