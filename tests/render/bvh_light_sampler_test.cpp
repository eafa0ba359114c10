// The light BVH's choice: a probability that sample() and pmf() agree on and that sums to one at most,
// no light that can reach a point ever culled (which would bias the path tracer), and the near
// lamps of a room preferred to the far ones.
#include "bvh_light_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sampling.h"

namespace woven {
namespace {

Light square(const glm::vec3& centre, float side, bool facingDown, bool twoSided, float L) {
    const float h = side / 2.0f;
    const glm::vec3 a = centre + glm::vec3(-h, 0, -h), b = centre + glm::vec3(h, 0, -h), c = centre + glm::vec3(h, 0, h);
    // Winding decides the front: (b - a) x (c - a) is -y, reversed for a lamp facing up.
    return facingDown ? Light::triangle(a, b, c, glm::vec3(L), twoSided) : Light::triangle(a, c, b, glm::vec3(L), twoSided);
}

// Every kind of light, scattered: lamps facing up and down, one- and two-sided, of powers over
// 1000x; points; spots; an environment.
std::vector<Light> mixedLights() {
    std::vector<Light> lights;
    Rng rng(7);
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 at(8.0f * rng.uniform() - 4.0f, 3.0f * rng.uniform(), 8.0f * rng.uniform() - 4.0f);
        lights.push_back(square(at, 0.05f + 0.3f * rng.uniform(), i % 2 == 0, i % 5 == 0, std::pow(10.0f, 3.0f * rng.uniform())));
    }
    for (int i = 0; i < 6; ++i) {
        PunctualLight p;
        p.type = i % 2 ? PunctualLight::Type::Point : PunctualLight::Type::Spot;
        p.position = {4.0f * rng.uniform() - 2.0f, 2.5f, 4.0f * rng.uniform() - 2.0f};
        p.direction = glm::normalize(glm::vec3(rng.uniform() - 0.5f, -1.0f, rng.uniform() - 0.5f));
        p.intensity = glm::vec3(20.0f);
        p.innerConeAngle = 0.2f;
        p.outerConeAngle = 0.5f;
        lights.push_back(Light::punctual(p));
    }
    Environment env;
    env.color = glm::vec3(0.2f);
    lights.push_back(Light::environment(env));
    Bounds scene{glm::vec3(-5.0f), glm::vec3(5.0f)};
    for (Light& l : lights) l.setSceneBounds(scene);
    return lights;
}

LightSampleContext randomContext(Rng& rng) {
    LightSampleContext ctx;
    ctx.p = {10.0f * rng.uniform() - 5.0f, 4.0f * rng.uniform() - 0.5f, 10.0f * rng.uniform() - 5.0f};
    if (rng.uniform() < 0.8f) ctx.n = sampleUniformSphere({rng.uniform(), rng.uniform()});  // else no surface
    return ctx;
}

TEST(BvhLightSampler, SampleAndPmfAgreeAndSumToAtMostOne) {
    const std::vector<Light> lights = mixedLights();
    const BvhLightSampler sampler(lights);
    Rng rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const LightSampleContext ctx = randomContext(rng);
        double sum = 0.0;
        for (int i = 0; i < int(lights.size()); ++i) sum += sampler.pmf(ctx, i);
        // Below one where a node's bounds let light through but neither child's does: then no
        // light is chosen, which biases nothing (pbrt-v4 does the same).
        EXPECT_LE(sum, 1.0 + 1e-4) << trial;
        EXPECT_GT(sum, 0.5) << trial;
        // Stratified u: each light's share of 4000 strata is its pmf, to within a stratum a
        // node boundary can split on each level down (a few per light); the rest choose none.
        std::vector<int> counts(lights.size(), 0);
        int none = 0;
        const int n = 4000;
        for (int k = 0; k < n; ++k) {
            float pmf = 0.0f;
            const int i = sampler.sample(ctx, (k + 0.5f) / n, &pmf);
            if (i < 0) {
                EXPECT_EQ(pmf, 0.0f);
                ++none;
                continue;
            }
            ASSERT_FLOAT_EQ(pmf, sampler.pmf(ctx, i));
            ++counts[size_t(i)];
        }
        for (size_t i = 0; i < lights.size(); ++i)
            EXPECT_NEAR(counts[i], n * sampler.pmf(ctx, int(i)), 8.0) << trial << " light " << i;
        EXPECT_NEAR(none, n * (1.0 - sum), 8.0 * 6) << trial;
    }
    EXPECT_EQ(sampler.pmf({}, -1), 0.0f);
    EXPECT_EQ(sampler.pmf({}, int(lights.size())), 0.0f);
}

// A light is culled only where it cannot shine: in front of a one-sided lamp, within a spot's
// cone, anywhere near a point light, its probability is above zero.
TEST(BvhLightSampler, NoLightThatReachesAPointIsCulled) {
    const std::vector<Light> lights = mixedLights();
    const BvhLightSampler sampler(lights);
    Rng rng(12);
    for (int trial = 0; trial < 2000; ++trial) {
        const LightSampleContext ctx = randomContext(rng);
        for (int i = 0; i < int(lights.size()); ++i) {
            const Light& light = lights[size_t(i)];
            bool reaches = true;
            if (const TriangleLight* t = light.get<TriangleLight>())
                reaches = t->twoSided || glm::dot(ctx.p - t->a, t->n) > 1e-4f;
            if (const SpotLight* s = light.get<SpotLight>())
                reaches = glm::dot(glm::normalize(ctx.p - s->position), s->direction) > s->cone.cosOuter + 1e-4f;
            if (reaches) {
                EXPECT_GT(sampler.pmf(ctx, i), 0.0f) << trial << " light " << i;
            }
        }
    }
}

TEST(BvhLightSampler, TheNearLampOfAGridOfEqualLampsIsPreferred) {
    std::vector<Light> lights;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) lights.push_back(square({-3.5f + i, 3.0f, -3.5f + j}, 0.1f, true, false, 100.0f));
    const BvhLightSampler sampler(lights);
    // Two triangles per lamp would be the same; one each here. Below lamp (2, 5), 1.5 m down:
    // power over squared distance gives it 1 / (1 + sum of the others' 1.5^2 / d^2 cos^2) of the
    // choice, about a fifth; the bounds are looser, so ask for 5x the power choice's 1/64.
    const LightSampleContext ctx{{-1.5f, 1.5f, 1.5f}, {0.0f, 1.0f, 0.0f}};
    EXPECT_GT(sampler.pmf(ctx, 2 * 8 + 5), 5.0f / 64.0f);
    // Behind every lamp (above the ceiling) none can shine: nothing is chosen.
    float pmf = 1.0f;
    EXPECT_EQ(sampler.sample({{0.0f, 4.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}, 0.5f, &pmf), -1);
    EXPECT_EQ(pmf, 0.0f);
}

// Lights at one place give no split: they are halved, and 70000 still fit the 64-bit trails.
TEST(BvhLightSampler, ManyLightsAtOnePlaceBuildAndSumToOne) {
    std::vector<Light> lights;
    PunctualLight p;
    p.position = {0.0f, 1.0f, 0.0f};
    for (int i = 0; i < 70000; ++i) lights.push_back(Light::punctual(p));
    const BvhLightSampler sampler(lights);
    const LightSampleContext ctx{{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    double sum = 0.0;
    for (int i = 0; i < int(lights.size()); ++i) sum += sampler.pmf(ctx, i);
    EXPECT_NEAR(sum, 1.0, 1e-3);
    EXPECT_NEAR(sampler.pmf(ctx, 12345), 1.0 / 70000.0, 1e-9);
}

}  // namespace
}  // namespace woven
