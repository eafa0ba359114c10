// Bsdf (bsdf.h): a Bxdf (a variant over the woven Ashikhmin-Shirley lobe and GltfBxdf) in its
// shading frame. World-space eval/pdf are the lobe's at the directions in the frame, samples come
// back in world space with the lobe's f, pdf and weight, and transmits() is forwarded.
#include <gtest/gtest.h>

#include <cmath>

#include "ashikhmin_shirley.h"
#include "bsdf.h"
#include "bsdf_test_util.h"
#include "gltf_bxdf.h"

namespace woven {
namespace {

using namespace woven::test;

bool near(const glm::vec3& a, const glm::vec3& b, float rel) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), rel * glm::max(glm::abs(a), glm::abs(b)) + 1e-30f));
}

Material roughMaterial(TestRng& rng) {
    Material m = randomMaterial(rng);
    // Roughness >= 0.3 everywhere: the world -> local round trip moves directions by ~1e-7, which
    // a sharp lobe would turn into large relative changes of f; 1e-4 then bounds the difference.
    m.roughness = rng.uniform(0.3, 1.0);
    m.clearcoatRoughness = rng.uniform(0.3, 1.0);
    m.sheenRoughness = rng.uniform(0.3, 1.0);
    return m;
}

TEST(BsdfWrapper, WorldEvalIsLocalEvalOfTransformedDirections) {
    TestRng rng(1234);
    for (int i = 0; i < 200; ++i) {
        const Material m = roughMaterial(rng);
        const GltfBxdf lobe(toInputs(m));
        const glm::vec3 n = toFloatUnit(rng.sphere());
        const Frame frame = i % 2 ? Frame::fromNormal(n) : Frame::fromNormalAndAxis(n, toFloatUnit(rng.sphere()));
        const Bsdf bsdf(frame, Bxdf(lobe));
        for (int j = 0; j < 20; ++j) {
            // Local directions first, then to world: the world BSDF must see the local ones.
            const glm::vec3 woLocal = toFloatUnit(rng.hemisphere() + glm::dvec3(0.0, 0.0, 0.05)), wiLocal = toFloatUnit(rng.sphere());
            const glm::vec3 wo = frame.toWorld(woLocal), wi = frame.toWorld(wiLocal);
            // Same arithmetic: bit for bit what the lobe gives for frame.toLocal of the world
            // directions...
            EXPECT_EQ(bsdf.eval(wo, wi), lobe.eval(frame.toLocal(wo), frame.toLocal(wi)));
            EXPECT_EQ(bsdf.pdf(wo, wi), lobe.pdf(frame.toLocal(wo), frame.toLocal(wi)));
            // ...and, up to the round trip's rounding, what it gives for the local directions:
            // the frame maps the normal's hemisphere to the lobe's z > 0.
            EXPECT_TRUE(near(bsdf.eval(wo, wi), lobe.eval(woLocal, wiLocal), 1e-4f))
                << describe(bsdf.eval(wo, wi)) << " vs " << describe(lobe.eval(woLocal, wiLocal)) << " " << describe(m);
            EXPECT_NEAR(bsdf.pdf(wo, wi), lobe.pdf(woLocal, wiLocal), 1e-4f * lobe.pdf(woLocal, wiLocal) + 1e-30f);
            // Light below the world normal only through a BSDF that transmits.
            if (glm::dot(wi, frame.z) < 0.0f && bsdf.eval(wo, wi) != glm::vec3(0.0f)) {
                EXPECT_TRUE(bsdf.transmits());
            }
        }
    }
}

TEST(BsdfWrapper, SamplesComeBackInWorldSpace) {
    TestRng rng(4321);
    for (int i = 0; i < 200; ++i) {
        const Material m = roughMaterial(rng);
        const GltfBxdf lobe(toInputs(m));
        const Frame frame = Frame::fromNormal(toFloatUnit(rng.sphere()));
        const Bsdf bsdf(frame, Bxdf(lobe));
        for (int j = 0; j < 20; ++j) {
            const glm::vec3 wo = frame.toWorld(toFloatUnit(rng.hemisphere() + glm::dvec3(0.0, 0.0, 0.05)));
            const glm::vec2 u = rng.u2();
            const float uc = rng.u();
            const auto world = bsdf.sample(wo, u, uc);
            const auto local = lobe.sample(frame.toLocal(wo), u, uc);
            ASSERT_EQ(world.has_value(), local.has_value());
            if (!world) continue;
            EXPECT_EQ(world->wi, frame.toWorld(local->wi));
            EXPECT_EQ(world->f, local->f);
            EXPECT_EQ(world->pdf, local->pdf);
            EXPECT_EQ(world->weight, local->weight);
            // The sampled side of the surface, in world space: below the normal only if it transmits.
            EXPECT_EQ(glm::dot(world->wi, frame.z) < 0.0f, local->wi.z < 0.0f);
            // Evaluating the world sample again goes through the frame twice: within rounding.
            EXPECT_TRUE(near(bsdf.eval(wo, world->wi), world->f, 1e-4f)) << describe(m);
            EXPECT_NEAR(bsdf.pdf(wo, world->wi), world->pdf, 1e-4f * world->pdf);
        }
    }
}

TEST(BsdfWrapper, TransmitsIsForwarded) {
    const Frame frame = Frame::fromNormal(glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f)));
    GltfBxdfInputs in;
    in.metallic = 0.0f;
    EXPECT_FALSE(Bsdf(frame, Bxdf(GltfBxdf(in))).transmits());
    in.transmission = 0.5f;
    EXPECT_TRUE(GltfBxdf(in).transmits());
    EXPECT_TRUE(Bxdf(GltfBxdf(in)).transmits());
    EXPECT_TRUE(Bsdf(frame, Bxdf(GltfBxdf(in))).transmits());
    in.metallic = 1.0f;  // a metal does not transmit, whatever its transmission factor
    EXPECT_FALSE(Bsdf(frame, Bxdf(GltfBxdf(in))).transmits());
    const AshikhminShirley woven(10.0f, 100.0f, 0.04f, glm::vec3(0.5f));
    EXPECT_FALSE(Bsdf(frame, Bxdf(woven)).transmits());
}

TEST(BsdfWrapper, WovenLobeThroughTheVariant) {
    // The variant dispatches to the woven lobe unchanged, and toBsdf keeps its frame.
    const AshikhminShirley lobe(300.0f, 20.0f, 0.04f, glm::vec3(0.6f, 0.4f, 0.2f));
    const Frame frame = Frame::fromNormalAndAxis(glm::normalize(glm::vec3(0.1f, 0.2f, 0.9f)), glm::vec3(1.0f, 0.0f, 0.0f));
    const SurfaceBsdf surface(frame, lobe);
    const Bsdf bsdf = toBsdf(surface);
    TestRng rng(77);
    for (int j = 0; j < 200; ++j) {
        const glm::vec3 wo = toFloatUnit(rng.sphere()), wi = toFloatUnit(rng.sphere());
        EXPECT_EQ(bsdf.eval(wo, wi), surface.eval(wo, wi));
        EXPECT_EQ(bsdf.pdf(wo, wi), surface.pdf(wo, wi));
        const glm::vec2 u = rng.u2();
        const float uc = rng.u();
        const auto a = bsdf.sample(wo, u, uc), b = surface.sample(wo, u, uc);
        ASSERT_EQ(a.has_value(), b.has_value());
        if (a) {
            EXPECT_EQ(a->wi, b->wi);
            EXPECT_EQ(a->weight, b->weight);
        }
    }
    EXPECT_EQ(bsdf.frame().z, frame.z);
    EXPECT_EQ(bsdf.shadingNormal(), frame.z);
}

}  // namespace
}  // namespace woven
