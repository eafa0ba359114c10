// The render passes (render_passes.h) against what the scene says: a woven plane seen from above
// at a known height under a grey sky. Depth is the distance along each pixel's ray to the plane,
// the albedo shows the warp's and the weft's colours where each is on top, the normal leans with
// the yarn bump, and the variance is the sample variance of the pixel's samples over their count,
// each sample rendered on its own (a frame is a pure function of its sample range); the direct
// light is what a one-bounce render of the same samples finds where nothing casts a shadow.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "test_scenes.h"

namespace woven {
namespace {

using test::quad;
using test::sceneWith;

constexpr float kHeight = 2.0f, kYfov = 0.6f;
constexpr int kWidth = 24, kHeightPx = 18;

// Red weft over blue warp in the default weave, bumped (c_y), coarse enough that each thread covers
// a few pixels; a grey sky lights it.
std::shared_ptr<SceneDescription> wovenPlane() {
    Material cloth;
    cloth.name = "cloth";
    WovenParams p;
    p.weft_color = glm::vec3(0.8f, 0.1f, 0.1f);
    p.warp_color = glm::vec3(0.1f, 0.1f, 0.8f);
    p.cy = 0.8f;
    cloth.woven = p;
    auto scene = sceneWith({quad("plane", {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0, 120.0f)}, {cloth});
    scene->camera.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, kHeight));
    scene->camera.yfov = kYfov;
    scene->hasCamera = true;
    scene->environment.color = glm::vec3(0.5f);
    return scene;
}

RenderSettings settings(int64_t first, int spp) {
    RenderSettings s;
    s.width = kWidth;
    s.height = kHeightPx;
    s.integrator = "path";
    s.firstSample = first;
    s.spp = spp;
    s.seed = 3;
    return s;
}

TEST(RenderPasses, DepthAlbedoAndNormalAreThoseOfTheFirstHit) {
    const FilmImage film = test::render(wovenPlane(), settings(0, 8));
    const RenderPasses passes = film.passes();
    const double tanHalf = std::tan(0.5 * kYfov), aspect = double(kWidth) / kHeightPx;
    int weftOnTop = 0, warpOnTop = 0, leaning = 0;
    for (int y = 0; y < kHeightPx; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + size_t(x);
            // The ray through the pixel's centre meets the plane at kHeight / cos: the depth
            // varies by under 0.1 % over a pixel at this field of view.
            const double dx = (2.0 * (x + 0.5) / kWidth - 1.0) * aspect * tanHalf, dy = (1.0 - 2.0 * (y + 0.5) / kHeightPx) * tanHalf;
            const double expected = kHeight * std::sqrt(1.0 + dx * dx + dy * dy);
            EXPECT_NEAR(passes.depth[i], expected, 2e-3 * expected) << x << ", " << y;
            const glm::vec3 a = passes.albedo.pixels[i], n = passes.normal.pixels[i];
            EXPECT_TRUE(a.r >= 0.0f && a.g >= 0.0f && a.b >= 0.0f && a.r <= 1.0f && a.g <= 1.0f && a.b <= 1.0f) << x << ", " << y;
            weftOnTop += a.r > 2.0f * a.b;
            warpOnTop += a.b > 2.0f * a.r;
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
            EXPECT_GT(n.z, 0.2f);  // c_y = 0.8 tilts the yarns' normals by up to about 65 degrees
            leaning += n.z < 0.999f;
        }
    // A plain weave shows each yarn on half its surface; mixed pixels fall in neither count.
    const int pixels = kWidth * kHeightPx;
    EXPECT_GT(weftOnTop, pixels / 5);
    EXPECT_GT(warpOnTop, pixels / 5);
    // The bump tilts the normal away from the plane's almost everywhere.
    EXPECT_GT(leaning, pixels / 2);
}

TEST(RenderPasses, VarianceIsTheSampleVarianceOfTheMean) {
    constexpr int kSamples = 5;
    const FilmImage film = test::render(wovenPlane(), settings(0, kSamples));
    std::vector<FilmImage> samples;
    for (int k = 0; k < kSamples; ++k) samples.push_back(test::render(wovenPlane(), settings(k, 1)));
    const RenderPasses passes = film.passes();
    int noisy = 0;
    for (size_t i = 0; i < film.radiance.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0, sumSq = 0.0;
            for (const FilmImage& s : samples) {
                const double v = s.radiance.pixels[i][c];
                sum += v;
                sumSq += v * v;
            }
            const double mean = sum / kSamples;
            const double expected = (sumSq - kSamples * mean * mean) / (kSamples - 1) / kSamples;
            // Both in double from the same float samples: they differ by rounding alone.
            EXPECT_NEAR(passes.variance.pixels[i][c], expected, 1e-5 * expected + 1e-12) << "pixel " << i;
            noisy += expected > 0.0;
        }
    EXPECT_GT(noisy, int(film.radiance.pixels.size()));  // most pixels' channels see noise
}

TEST(RenderPasses, DirectLightIsZeroWithTheEnvironmentAlone) {
    // The environment's light is left out of the pass: only sampling finds it, with noise.
    const RenderPasses passes = test::render(wovenPlane(), settings(0, 4)).passes();
    for (const glm::vec3& d : passes.direct.pixels) EXPECT_EQ(d, glm::vec3(0.0f));
}

TEST(RenderPasses, DirectLightIsTheOneBounceLightOfAnUnshadowedPointLight) {
    // Under one point light, the plane alone and the sky black, a one-bounce path tracer's sample
    // is its next-event estimate at the first hit: the light's intensity over the squared distance
    // times the BSDF and cosine there, what the pass sums. A pass that took another point of the
    // pixel, missed the cosine or the distance, or added the environment would differ by far more
    // than rounding (1e-4).
    auto scene = wovenPlane();
    scene->environment.color = glm::vec3(0.0f);
    PunctualLight light;
    light.position = glm::vec3(0.4f, -0.3f, 1.5f);
    light.intensity = glm::vec3(3.0f, 2.0f, 1.0f);
    scene->lights.push_back(light);
    RenderSettings s = settings(0, 6);
    s.maxDepth = 1;
    const FilmImage film = test::render(scene, s);
    const RenderPasses passes = film.passes();
    int lit = 0;
    for (size_t i = 0; i < film.radiance.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float beauty = film.radiance.pixels[i][c];
            EXPECT_NEAR(passes.direct.pixels[i][c], beauty, 1e-4f * beauty + 1e-7f) << "pixel " << i << " channel " << c;
            lit += beauty > 0.0f;
        }
    EXPECT_GT(lit, int(film.radiance.pixels.size()));
}

}  // namespace
}  // namespace woven
