// The glTF material in the renderer, against answers that do not come from core: a white
// furnace, alpha cut-outs seen through by every kind of ray, and a textured emitter whose light
// sampling must see its texels.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <cmath>

#include "render_job.h"
#include "render_scene.h"
#include "sampling.h"
#include "test_scenes.h"

namespace woven {
namespace {

using test::lookingDown;
using test::occludedFrom;
using test::quad;
using test::render;
using test::sceneWith;
using test::uvSphere;

constexpr double kPi = 3.14159265358979323846;

// A pure Lambert reflector in glTF terms: a dielectric whose KHR_materials_specular factor is 0
// (F0 = F90 = 0), so only the diffuse lobe remains.
Material lambert(float albedo) {
    Material m;
    m.baseColor = glm::vec4(glm::vec3(albedo), 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.specular = 0.0f;
    return m;
}

class GltfFurnace : public ::testing::TestWithParam<const char*> {};

// A white Lambert sphere in a uniform environment of radiance 1 returns exactly 1 everywhere:
// whatever it reflects is the environment, each bounce losing nothing.
TEST_P(GltfFurnace, WhiteLambertSphereReturnsTheEnvironment) {
    auto scene = sceneWith({uvSphere(1.0f, 24, 48, 0)}, {lambert(1.0f)});
    scene->environment.color = glm::vec3(1.0f);
    scene->camera.cameraToWorld = glm::inverse(glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0)));
    scene->camera.yfov = 0.5f;
    scene->hasCamera = true;
    RenderSettings s;
    s.width = s.height = 16;
    s.spp = 64;
    s.integrator = GetParam();
    s.maxDepth = 16;
    const FilmImage film = render(scene, s);
    double sum = 0.0, sumSq = 0.0;
    const int n = s.width * s.height;
    for (const glm::vec3& p : film.radiance.pixels) {
        sum += p.g;
        sumSq += double(p.g) * p.g;
    }
    const double mean = sum / n, standardError = std::sqrt((sumSq / n - mean * mean) / (n - 1));
    // 5 standard errors of the mean (a few thousandths), plus Russian roulette's and float's
    // nothing: an energy leak or gain of 1 % fails.
    EXPECT_NEAR(mean, 1.0, 5.0 * standardError + 1e-4) << GetParam() << ", standard error " << standardError;
    EXPECT_LT(standardError, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Integrators, GltfFurnace, ::testing::Values("path", "bdpt"));

class GltfSides : public ::testing::TestWithParam<const char*> {};

double meanLuminance(const FilmImage& film) {
    double sum = 0.0;
    for (const glm::vec3& p : film.radiance.pixels) sum += luminance(p);
    return sum / double(film.radiance.pixels.size());
}

// A black card filling the view in a white environment. Single-sided and seen from behind, the
// camera sees the environment through it, as glTF viewers show it; from the front, or
// double-sided, it sees the card.
TEST_P(GltfSides, CameraSeesThroughTheBackOfSingleSidedSurfaces) {
    const auto frame = [&](bool doubleSided, float cameraZ) {
        Material black = lambert(0.0f);
        black.doubleSided = doubleSided;
        auto scene = sceneWith({quad("card", {-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}, 0)}, {black});
        scene->environment.color = glm::vec3(1.0f);
        scene->camera.cameraToWorld = glm::inverse(glm::lookAt(glm::vec3(0, 0, cameraZ), glm::vec3(0), glm::vec3(0, 1, 0)));
        scene->camera.yfov = 0.5f;
        scene->hasCamera = true;
        RenderSettings s;
        s.width = s.height = 8;
        s.spp = 4;
        s.integrator = GetParam();
        return meanLuminance(render(scene, s));
    };
    EXPECT_NEAR(frame(false, -3.0f), 1.0, 1e-5);  // its back: the environment
    EXPECT_EQ(frame(false, 3.0f), 0.0);           // its front
    EXPECT_EQ(frame(true, -3.0f), 0.0);
    EXPECT_EQ(frame(true, 3.0f), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Integrators, GltfSides, ::testing::Values("path", "bdpt"));

// The camera looks through the back of a single-sided card at a white floor lit by a point light
// under the card. BDPT's light paths that end on the camera see the floor through the card as
// camera rays do: were the card in their way, its light-tracing strategy would be lost and BDPT
// 9 % darker than the path tracer (0.06 % apart with it).
TEST(GltfSidesIntegrators, BdptAgreesWithThePathTracerThroughACulledBack) {
    Material card = lambert(0.0f);
    card.doubleSided = false;
    auto scene = sceneWith({quad("card", {-5, 0.5f, -5}, {5, 0.5f, -5}, {5, 0.5f, 5}, {-5, 0.5f, 5}, 0),  // faces -y
                            quad("floor", {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}, {-20, 0, -20}, 1)},  // faces +y
                           {card, lambert(1.0f)});
    PunctualLight bulb;
    bulb.position = glm::vec3(0.0f, 0.3f, 0.0f);
    scene->lights = {bulb};
    scene->camera = lookingDown(2.0f, 0.4f);
    scene->hasCamera = true;
    RenderSettings s;
    s.width = s.height = 16;
    s.spp = 256;
    s.maxDepth = 1;
    s.integrator = "path";
    const double path = meanLuminance(render(scene, s));
    s.integrator = "bdpt";
    const double bdpt = meanLuminance(render(scene, s));
    EXPECT_GT(path, 0.5);  // about I / (pi h^2) = 3.5 below the bulb
    EXPECT_NEAR(bdpt, path, 0.02 * path);
}

// A black quad at z = 1 (alpha cut out where u < 0.5, by a 2 x 1 texture) over a floor at z = 0.
std::shared_ptr<SceneDescription> cutOutOverFloor(AlphaMode mode) {
    Material card = lambert(0.0f);
    card.alphaMode = mode;
    card.baseColorTexture.image = 0;
    card.baseColorTexture.nearest = true;
    Material floor = lambert(0.5f);
    auto scene = sceneWith({quad("card", {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, 0),
                            quad("floor", {-1, -1, 0}, {2, -1, 0}, {2, 2, 0}, {-1, 2, 0}, 1)},
                           {card, floor});
    TextureImage alpha;
    alpha.width = 2;
    alpha.height = 1;
    alpha.bytes = {{255, 255, 255, 0}, {255, 255, 255, 255}};
    scene->textures = {alpha};
    return scene;
}

TEST(GltfAlpha, CutOutsLetCameraAndShadowRaysThrough) {
    RenderScene scene(cutOutOverFloor(AlphaMode::Mask));
    const auto down = [](float x, float y) { return Ray{{x, y, 3.0f}, {0, 0, -1}}; };
    EXPECT_EQ(scene.intersect(down(0.25f, 0.5f))->mesh, 1);  // through the cut-out to the floor
    EXPECT_EQ(scene.intersect(down(0.75f, 0.5f))->mesh, 0);  // the opaque half
    EXPECT_FALSE(occludedFrom(scene, {0.25f, 0.5f, 3.0f}, {0.25f, 0.5f, 0.01f}));
    EXPECT_TRUE(occludedFrom(scene, {0.75f, 0.5f, 3.0f}, {0.75f, 0.5f, 0.01f}));
}

TEST(GltfAlpha, BlendLetsThroughInProportionToTransparency) {
    auto desc = cutOutOverFloor(AlphaMode::Blend);
    desc->textures[0].bytes = {{255, 255, 255, 64}, {255, 255, 255, 192}};  // alpha 0.25 | 0.75
    RenderScene scene(desc);
    Rng rng(11);
    int throughLeft = 0, throughRight = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        // Rays from different origins: stochastic transparency draws per ray and point.
        const glm::vec2 o = rng.uniform2();
        const glm::vec3 target(0.05f + 0.4f * o.x, 0.05f + 0.9f * o.y, 1.0f);
        const glm::vec3 from = target + glm::vec3(0.3f * rng.uniform() - 0.15f, 0.2f, 2.0f);
        throughLeft += scene.intersect(Ray{from, glm::normalize(target - from)})->mesh == 1;
        const glm::vec3 right = target + glm::vec3(0.5f, 0, 0);
        throughRight += !occludedFrom(scene, right + glm::vec3(0, 0, 2), right - glm::vec3(0, 0, 0.99f));
    }
    // Binomial, p = 0.75 and 0.25: 5 standard deviations is 0.015.
    const double tolerance = 5.0 * std::sqrt(0.75 * 0.25 / n);
    EXPECT_NEAR(throughLeft / double(n), 0.75, tolerance);
    EXPECT_NEAR(throughRight / double(n), 0.25, tolerance);
}

// A 2 x 2 emitter at height 1 facing down whose texture is black for x < 0 and white for x > 0,
// over a white Lambert floor. The floor's radiance below the centre is E / pi with E the
// irradiance from the white half alone, worked out here by quadrature.
TEST(GltfEmission, TexturedEmitterLightsAsItsTexelsSay) {
    Material lamp;
    lamp.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    lamp.specular = 0.0f;
    lamp.emission = glm::vec3(2.0f);
    lamp.emissiveTexture.image = 0;
    lamp.emissiveTexture.nearest = true;
    lamp.emissiveTexture.srgb = true;
    lamp.doubleSided = false;
    auto scene = sceneWith({quad("lamp", {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, 0),  // faces -y
                            quad("floor", {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, 1)},
                           {lamp, lambert(1.0f)});
    TextureImage half;
    half.width = 2;
    half.height = 1;
    half.bytes = {{0, 0, 0, 255}, {255, 255, 255, 255}};
    scene->textures = {half};
    scene->camera = lookingDown(0.5f, 0.02f);
    scene->hasCamera = true;

    // E = L int cos cos' / r^2 dA over x in [0, 1], z in [-1, 1], at height h = 1.
    double E = 0.0;
    const int q = 400;
    for (int i = 0; i < q; ++i)
        for (int j = 0; j < q; ++j) {
            const double x = (i + 0.5) / q, z = -1.0 + 2.0 * (j + 0.5) / q;
            const double r2 = x * x + z * z + 1.0;
            E += 1.0 / (r2 * r2) * (1.0 / q) * (2.0 / q);  // cos = cos' = 1 / r
        }
    const double expected = 2.0 * E / kPi;

    for (const char* integrator : {"path", "bdpt"}) {
        RenderSettings s;
        s.width = s.height = 8;
        s.spp = 256;
        s.integrator = integrator;
        s.maxDepth = 1;
        const FilmImage film = render(scene, s);
        double sum = 0.0, sumSq = 0.0;
        for (const glm::vec3& p : film.radiance.pixels) {
            sum += p.r;
            sumSq += double(p.r) * p.r;
        }
        const int n = s.width * s.height;
        const double mean = sum / n, standardError = std::sqrt((sumSq / n - mean * mean) / (n - 1));
        // The view covers 1 cm of floor, where E varies by well under 0.1 %. A light sampled by
        // its mean radiance instead of its texels is off by a third of this value.
        EXPECT_NEAR(mean, expected, 5.0 * standardError + 2e-3 * expected) << integrator;
    }
}

}  // namespace
}  // namespace woven
