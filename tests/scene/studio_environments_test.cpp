// The environments woven generates for look development: each an image of light where its name
// says, and reached by --environment NAME.
#include <gtest/gtest.h>

#include <gmock/gmock.h>

#include "environment_mapping.h"
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
