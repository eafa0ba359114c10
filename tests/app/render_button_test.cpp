// The Render button's frame (`woven preview --headless --final`, the window's code path: the
// preview's initial camera, FinalRender, the shared frame options and writer) equals
// `woven render`'s for the same scene and options: bit for bit, since both run the same
// RenderJob with the same camera, seed and sample range.
#include <gtest/gtest.h>
#include <unistd.h>

#include <gmock/gmock.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "../common/run_woven.h"
#include "../scene/gltf_builder.h"
#include "../scene/temp_dir.h"
#include "frame_io.h"
#include "image_io.h"

namespace woven {
namespace {

using test::TempDir;

// Renders `scene` both ways with `options`; expects identical radiance and sample counts.
ExrImage expectRenderButtonEqualsRender(const TempDir& dir, const std::string& scene, const std::string& options) {
    const std::string rendered = dir.file("render.exr"), button = dir.file("button.exr");
    EXPECT_EQ(test::runWovenWithErrors("render " + scene + " " + options + " -o " + rendered), 0);
    EXPECT_EQ(test::runWovenWithErrors("preview " + scene + " --headless --final " + options + " --screenshot " + button), 0);
    const ExrImage a = readExr(rendered), b = readExr(button);
    EXPECT_EQ(a.image.width, b.image.width);
    EXPECT_EQ(a.image.height, b.image.height);
    EXPECT_TRUE(a.image.pixels == b.image.pixels) << "the Render button's radiance differs from woven render's";
    EXPECT_EQ(a.sampleCount, b.sampleCount);
    return a;
}

double meanLuminance(const Image& image) {
    double sum = 0.0;
    for (const glm::vec3& c : image.pixels) sum += 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    return sum / double(image.pixels.size());
}

TEST(RenderButton, SceneCameraEqualsWovenRender) {
    TempDir dir;
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    const ExrImage plain = expectRenderButtonEqualsRender(dir, scene, "--width 40 --height 30 --spp 2 --integrator path --seed 3");
    EXPECT_EQ(plain.image.width, 40);
    EXPECT_EQ(plain.sampleCount.front(), 2.0f);
    ASSERT_GT(meanLuminance(plain.image), 0.0);

    // Tuned parameters and the other integrator: still equal, and not the untuned frame.
    const ExrImage tuned = expectRenderButtonEqualsRender(
        dir, scene,
        "--width 40 --height 30 --spp 2 --integrator bdpt --seed 3 "
        "--woven 'Cloth={\"pattern\":[9,1,3],\"ex\":400,\"weft_color\":[0.9,0.1,0.1]}'");
    EXPECT_FALSE(tuned.image.pixels == plain.image.pixels);
}

TEST(RenderButton, SizeSamplesAndIntegratorDefaultToTheScenesAsInWovenRender) {
    TempDir dir;
    // converge_open.json asks for 320x240; both take the scene's spp default (64) unless told:
    // --spp 1 here keeps it fast, the size comes from the scene in both.
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/converge_open.json";
    const ExrImage image = expectRenderButtonEqualsRender(dir, scene, "--spp 1 --integrator path");
    EXPECT_EQ(image.image.width, 320);
    EXPECT_EQ(image.image.height, 240);
}

TEST(RenderButton, GltfWithoutCameraIsFramedTheSameWay) {
    TempDir dir;
    // A woven floor lit by a point light, no camera: both frame its bounds with sceneCamera().
    test::GltfBuilder b;
    const int positions = b.addPositions({{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}});
    const int normals = b.addVec3({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}});
    const int uvs = b.addVec2({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const int indices = b.addIndices({0, 2, 1, 0, 3, 2});
    const int material = b.addMaterial({{"name", "Cloth"}, {"extras", {{"woven", {{"pattern", {1, 2, 1}}, {"repeat", {6, 6}}}}}}});
    const int mesh = b.addMesh({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}}},
                                {"indices", indices},
                                {"material", material}});
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 30.0}}};
    b.setScene({b.addNode({{"mesh", mesh}}),
                b.addNode({{"translation", {0.3, 1.5, 0.8}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})});
    const std::string gltf = dir.file("floor.gltf");
    b.writeGltf(gltf);

    const ExrImage image = expectRenderButtonEqualsRender(dir, gltf, "--width 32 --height 24 --spp 2 --integrator path");
    // The framing camera looks down at the floor's centre from 29 degrees above the front, the
    // bounding sphere filling the view: the floor covers about 17% of the image (a band under
    // the centre), left-right symmetric. A camera aimed elsewhere or from below sees no floor.
    size_t lit = 0;
    double columnSum = 0.0;
    for (int y = 0; y < image.image.height; ++y)
        for (int x = 0; x < image.image.width; ++x) {
            const glm::vec3 c = image.image.at(x, y);
            if (c.r + c.g + c.b <= 0.0f) continue;
            ++lit;
            columnSum += x + 0.5;
        }
    EXPECT_GT(lit, image.image.pixels.size() / 10);
    ASSERT_GT(lit, 0u);
    EXPECT_NEAR(columnSum / double(lit), 0.5 * image.image.width, 0.05 * image.image.width);
}

TEST(RenderButton, PngsGoThroughTheSameDisplayTransform) {
    TempDir dir;
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    const std::string options = " --width 24 --height 18 --spp 1 --integrator path --exposure 1 --tone-map reinhard";
    ASSERT_EQ(test::runWovenWithErrors("render " + scene + options + " -o " + dir.file("r.png")), 0);
    ASSERT_EQ(test::runWovenWithErrors("preview " + scene + " --headless --final" + options + " --screenshot " + dir.file("b.png")), 0);
    ASSERT_EQ(test::runWovenWithErrors("render " + scene + options + " -o " + dir.file("r.exr")), 0);
    const Image r = readImage(dir.file("r.png"), ChannelEncoding::Linear);
    const Image b = readImage(dir.file("b.png"), ChannelEncoding::Linear);
    EXPECT_TRUE(r.pixels == b.pixels);
    // And the PNG is the EXR through displayColor with exposure 1 and Reinhard.
    const Image linear = readExr(dir.file("r.exr")).image;
    ASSERT_EQ(linear.pixels.size(), r.pixels.size());
    for (size_t i = 0; i < r.pixels.size(); ++i) {
        const glm::u8vec3 expected = displayColor(linear.pixels[i], {1.0f, ToneMap::Reinhard});
        for (int c = 0; c < 3; ++c) EXPECT_EQ(std::lround(r.pixels[i][c] * 255.0f), expected[c]) << "pixel " << i;
    }
}

TEST(RenderButton, BadOptionsFailClearlyAndWriteNothing) {
    TempDir dir;
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    std::string errors;
    EXPECT_NE(test::runWovenWithErrors("preview " + scene + " --headless --final --spp 1 --woven 'NoSuchMaterial={}' --screenshot " +
                      dir.file("x.exr"),
                  &errors),
              0);
    EXPECT_THAT(errors, testing::HasSubstr("'NoSuchMaterial' names nothing"));
    EXPECT_THAT(errors, testing::HasSubstr("'Cloth'"));  // the names it has
    EXPECT_NE(test::runWovenWithErrors("preview " + scene + " --headless --final --spp 1 --tone-map sepia --screenshot " + dir.file("y.png"),
                  &errors),
              0);
    EXPECT_THAT(errors, testing::HasSubstr("--tone-map"));
    EXPECT_NE(test::runWovenWithErrors("preview " + scene + " --headless --final --spp 1 --screenshot " + dir.file("z.tiff"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("z.tiff: unknown image type '.tiff' (expected .exr or .png)"));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace woven
