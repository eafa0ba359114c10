// The environments woven generates for look development: each an image of light where its name
// says, and reached by --environment NAME.
#include <gtest/gtest.h>

#include <cmath>

#include <gmock/gmock.h>

#include "environment_mapping.h"
#include "math_constants.h"
#include "scene_lighting.h"
#include "studio_environments.h"

namespace woven {
namespace {

// The direction of the brightest pixel.
glm::vec3 brightest(const Environment& env) {
    const Image& image = *env.image;
    int best = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        if (image.pixels[i].g > image.pixels[size_t(best)].g) best = int(i);
    return equirectDirection({(best % image.width + 0.5f) / image.width, (best / image.width + 0.5f) / image.height});
}

glm::vec3 radianceTowards(const Environment& env, const glm::vec3& d) {
    const glm::vec2 uv = equirectUv(d);
    const Image& image = *env.image;
    return image.at(std::min(int(uv.x * image.width), image.width - 1), std::min(int(uv.y * image.height), image.height - 1));
}

// What lights a model with no light of its own is on average as bright as `--environment 1`, so
// a model is not darker at the defaults than a viewer's grey shows it: the mean radiance over the
// sphere is 1, and a surface facing any way but the floor gets at least half the irradiance a
// uniform radiance of 1 gives (pi). The floor is darker, as a studio's is.
TEST(StudioEnvironments, TheDefaultStudioIsAsBrightOnAverageAsAUniformEnvironmentOfOne) {
    const Environment studio = studioEnvironment();
    const Image& image = *studio.image;
    const glm::vec3 facing[] = {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 0, -1}};
    double radiance = 0.0, solidAngle = 0.0, irradiance[5] = {};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / image.width, (y + 0.5f) / image.height});
            const double dOmega = std::sin(kPiDouble * (y + 0.5) / image.height) * (2.0 * kPiDouble / image.width) *
                                  (kPiDouble / image.height);
            radiance += dOmega * image.at(x, y).g;
            solidAngle += dOmega;
            for (int n = 0; n < 5; ++n) irradiance[n] += dOmega * image.at(x, y).g * std::max(glm::dot(d, facing[n]), 0.0f);
        }
    EXPECT_NEAR(radiance / solidAngle, 1.0, 1e-3);
    for (int n = 0; n < 5; ++n) EXPECT_GT(irradiance[n], 0.5 * kPiDouble) << "facing " << n;
}

TEST(StudioEnvironments, EachIsAnImageOfLightWhereItsNameSays) {
    ASSERT_EQ(studioEnvironmentNames(), "studio, softbox, window or overcast");
    for (const StudioEnvironment& studio : studioEnvironments()) {
        const Environment env = studio.make();
        ASSERT_TRUE(env.image) << studio.name;
        EXPECT_EQ(env.color, glm::vec3(1.0f));
        for (const glm::vec3& p : env.image->pixels) ASSERT_TRUE(p.r >= 0.0f && std::isfinite(p.r)) << studio.name;
    }
    EXPECT_GT(brightest(findStudioEnvironment("softbox")->make()).y, 0.5f);  // above
    EXPECT_LT(brightest(findStudioEnvironment("window")->make()).x, -0.5f);  // on the left
    const Environment overcast = findStudioEnvironment("overcast")->make();
    const glm::vec3 zenith = radianceTowards(overcast, {0, 1, 0}), horizon = radianceTowards(overcast, {1, 0.1f, 0});
    const glm::vec3 ground = radianceTowards(overcast, {0, -1, 0});
    EXPECT_NEAR(zenith.g / horizon.g, 3.0f / (1.0f + 2.0f * 0.0995f), 0.1f);  // CIE overcast: (1 + 2 cos theta) / 3
    EXPECT_LT(ground.g, horizon.g);
    EXPECT_EQ(findStudioEnvironment("studio")->make().image->pixels, studioEnvironment().image->pixels);
    EXPECT_EQ(findStudioEnvironment("sunset"), nullptr);
}

TEST(StudioEnvironments, EnvironmentOptionTakesTheirNames) {
    const Environment window = environmentFromOption("window");
    ASSERT_TRUE(window.image);
    EXPECT_EQ(window.image->pixels, findStudioEnvironment("window")->make().image->pixels);
}

}  // namespace
}  // namespace woven
