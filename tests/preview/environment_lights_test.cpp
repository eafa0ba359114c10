// The environment in the preview: as it lights (environmentLights: a sun in an HDR image becomes
// a directional light from the sun's direction carrying its irradiance, the rest stays ambient,
// and no energy is lost or made) and as it is seen behind the scene (core's Light::Le).
#include <gtest/gtest.h>

#include <cmath>

#include "flat_cloth.h"
#include "gl_test_context.h"
#include "light.h"
#include "preview_lights.h"

namespace woven {
namespace {

constexpr int kW = 256, kH = 128;

// Solid angle of pixel row y of a kW x kH equirectangular image, per pixel.
double pixelSolidAngle(int y) { return 2.0 * M_PI / kW * (std::cos(M_PI * y / kH) - std::cos(M_PI * (y + 1) / kH)); }

Environment skyWithSuns(const std::vector<std::pair<glm::ivec2, float>>& suns) {
    auto image = std::make_shared<Image>();
    image->width = kW;
    image->height = kH;
    image->pixels.assign(size_t(kW) * kH, glm::vec3(0.5f));
    for (const auto& [at, radiance] : suns)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) image->at(at.x + dx, at.y + dy) = glm::vec3(radiance);
    Environment env;
    env.image = image;
    env.color = glm::vec3(1.0f, 0.9f, 0.8f);
    env.rotation = 0.7f;
    return env;
}

double totalPower(const Environment& env) {
    double sum = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) sum += env.image->at(x, y).r * pixelSolidAngle(y);
    return sum;
}

TEST(EnvironmentLights, ConstantEnvironmentIsAllAmbient) {
    Environment env;
    env.color = glm::vec3(0.2f, 0.3f, 0.4f);
    const EnvironmentLights e = environmentLights(env, 4);
    EXPECT_TRUE(e.lights.empty());
    EXPECT_EQ(e.ambient, env.color);
}

TEST(EnvironmentLights, SunBecomesADirectionalLightFromItsDirection) {
    const glm::ivec2 sun(40, 30);  // u = 40.5/256, v = 30.5/128: 43 degrees from the zenith
    const Environment env = skyWithSuns({{sun, 2000.0f}});
    const EnvironmentLights e = environmentLights(env, 4);
    ASSERT_EQ(e.lights.size(), 1u);
    const PreviewLight& l = e.lights[0];
    EXPECT_EQ(l.type, PreviewLight::Directional);

    // The sun's direction from the mapping written out (scene_description.h): theta from +y,
    // phi from -z towards +x, then turned 0.7 rad about +y (-z towards -x).
    const double theta = M_PI * (sun.y + 0.5) / kH, phi = 2.0 * M_PI * (sun.x + 0.5) / kW, a = 0.7;
    const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
    const glm::dvec3 expected(d.x * std::cos(a) + d.z * std::sin(a), d.y, -d.x * std::sin(a) + d.z * std::cos(a));
    const double angle = std::acos(std::clamp(glm::dot(-glm::dvec3(glm::normalize(l.position)), expected), -1.0, 1.0));
    EXPECT_LT(angle, 0.5 * M_PI / 180.0);  // the cells are 1.4 degrees; the blob is centred

    double sunPower = 0.0;
    for (int dy = -1; dy <= 1; ++dy) sunPower += 3 * 2000.0 * pixelSolidAngle(sun.y + dy);
    // The region's cells also hold a few sky pixels at 0.5: well under 0.1% of the sun's.
    EXPECT_NEAR(l.intensity.r, sunPower, 1e-3 * sunPower);
    EXPECT_NEAR(l.intensity.b / l.intensity.r, 0.8, 1e-5);  // times the environment's colour
    // Energy: what the light carries plus the ambient over the sphere is the image's total.
    EXPECT_NEAR(l.intensity.r + 4.0 * M_PI * e.ambient.r, totalPower(env), 1e-4 * totalPower(env));
    EXPECT_NEAR(e.ambient.r, 0.5, 0.01);
}

TEST(EnvironmentLights, OnlyTheBrightestRegionsBecomeLightsTheRestStaysAmbient) {
    const Environment env = skyWithSuns({{{20, 20}, 500.0f}, {{80, 40}, 3000.0f}, {{140, 60}, 1000.0f},
                                         {{200, 30}, 2000.0f}, {{60, 90}, 800.0f}, {{180, 100}, 1500.0f}});
    const EnvironmentLights e = environmentLights(env, 4);
    ASSERT_EQ(e.lights.size(), 4u);
    for (size_t i = 1; i < e.lights.size(); ++i) EXPECT_GT(e.lights[i - 1].intensity.r, e.lights[i].intensity.r);
    double carried = 0.0;
    for (const PreviewLight& l : e.lights) carried += l.intensity.r;
    EXPECT_NEAR(carried + 4.0 * M_PI * e.ambient.r, totalPower(env), 1e-4 * totalPower(env));
    // The two dimmest suns (500 and 800) stay in the ambient, above the sky's 0.5.
    EXPECT_GT(e.ambient.r, 0.5);
}

TEST(EnvironmentLights, ABrightRingHasNoOneDirectionAndStaysAmbient) {
    Environment env = skyWithSuns({});
    auto image = std::make_shared<Image>(*env.image);
    for (int x = 0; x < kW; ++x) image->at(x, kH / 2) = glm::vec3(100.0f);  // a glowing horizon
    image->at(5, 5) = glm::vec3(-50.0f);  // noise from a denoiser: black, as core reads it
    env.image = image;
    const EnvironmentLights e = environmentLights(env, 4);
    EXPECT_TRUE(e.lights.empty());
    double total = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) total += std::max(image->at(x, y).r, 0.0f) * pixelSolidAngle(y);
    EXPECT_NEAR(4.0 * M_PI * e.ambient.r, total, 1e-4 * total);
}

TEST(EnvironmentBackground, EveryPixelSeesWhatCoresLeGivesForItsRay) {
    // An image whose every texel differs, turned and tinted, behind an empty scene.
    auto image = std::make_shared<Image>();
    image->width = 64;
    image->height = 32;
    image->pixels.resize(64 * 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) image->at(x, y) = glm::vec3(x / 64.0f, y / 32.0f, float((x * 7 + y * 13) % 17) / 17.0f);
    SceneDescription scene;
    scene.environment.image = image;
    scene.environment.color = glm::vec3(2.0f, 1.5f, 1.0f);
    scene.environment.rotation = 1.1f;
    scene.camera = lookAt({0.3f, 0.2f, 0.1f}, {1.0f, 0.8f, -0.6f}, {0, 1, 0}, 1.4f);  // wide, looking up
    const int w = 160, h = 120;
    const Image preview = test::previewRadiance(scene, w, h);
    const Light environment = Light::environment(scene.environment);
    size_t same = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 expected = environment.Le(test::cameraRayDirection(scene.camera, x + 0.5f, y + 0.5f, w, h));
            same += glm::all(glm::lessThanEqual(glm::abs(preview.at(x, y) - expected), glm::vec3(1e-5f)));
        }
    // Both take the nearest texel; a ray within rounding of a texel edge may pick its neighbour
    // on one side and not the other: 0.5% of the pixels at most. A wrong rotation, flip or
    // mapping gets most of them wrong.
    EXPECT_GT(double(same), 0.995 * w * h);
}

}  // namespace
}  // namespace woven
