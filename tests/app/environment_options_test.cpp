// --environment-rotation and --environment-intensity, which `woven render` and `woven preview`
// share (frame_options.h): the look-development light of issue 47 on the command line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <gmock/gmock.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "../common/run_woven.h"
#include "../scene/gltf_builder.h"
#include "../scene/temp_dir.h"
#include "display_transform.h"
#include "frame_io.h"

namespace woven {
namespace {

using test::TempDir;

const std::string kScene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
const std::string kFrame = " --width 32 --height 24 --spp 2 --integrator path --no-denoise --noise-threshold 0";

Image render(const TempDir& dir, const std::string& name, const std::string& options) {
    const std::string path = dir.file(name + ".exr");
    EXPECT_EQ(test::runWovenWithErrors("render " + kScene + kFrame + " " + options + " -o " + path), 0) << options;
    return readExr(path).image;
}

TEST(EnvironmentOptions, IntensityScalesTheEnvironment) {
    TempDir dir;
    // 0.5 x 2 is 1 exactly: the same light, the same frame bit for bit.
    const Image scaled = render(dir, "scaled", "--environment 0.5 --environment-intensity 2");
    const Image plain = render(dir, "plain", "--environment 1");
    EXPECT_TRUE(scaled.pixels == plain.pixels);
    EXPECT_FALSE(render(dir, "dim", "--environment 0.5").pixels == plain.pixels);
}

// A dim sky with one bright window towards +x (u = 0.25), a little above the horizon, as a PNG.
std::string skyWithAWindow(const TempDir& dir) {
    Image sky;
    sky.width = 32;
    sky.height = 16;
    sky.pixels.assign(size_t(sky.width) * sky.height, glm::vec3(0.02f));
    for (int y = 5; y < 8; ++y)
        for (int x = 7; x < 10; ++x) sky.at(x, y) = glm::vec3(1.0f);
    const std::string file = dir.file("sky.png");
    writePng(file, sky, {0.0f, ToneMap::Clamp});
    return file;
}

TEST(EnvironmentOptions, RotationTurnsAnImage) {
    TempDir dir;
    const std::string file = skyWithAWindow(dir);
    const Image unturned = render(dir, "a", "--environment " + file);
    EXPECT_TRUE(render(dir, "b", "--environment " + file + " --environment-rotation 0").pixels == unturned.pixels);
    EXPECT_FALSE(render(dir, "c", "--environment " + file + " --environment-rotation 90").pixels == unturned.pixels);
}

// A white box turned 45 degrees about +y, seen from the front (no camera: the framing one): the
// face whose normal is (1, 0, 1) / sqrt 2 fills the right of the image, the one of (-1, 0, 1) / sqrt 2
// the left.
std::string turnedBox(const TempDir& dir) {
    test::GltfBuilder b;
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
    const glm::mat3 turn(glm::vec3(0.7071068f, 0, 0.7071068f), glm::vec3(0, 1, 0), glm::vec3(-0.7071068f, 0, 0.7071068f));
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = side;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (side < 0.0f) std::swap(u, v);  // counter-clockwise seen from outside
            const uint32_t first = uint32_t(positions.size());
            for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                positions.push_back(turn * (0.5f * (n + c.x * u + c.y * v)));
                normals.push_back(turn * n);
            }
            for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(first + i);
        }
    const int material = b.addMaterial({{"name", "White"}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}}});
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(positions)}, {"NORMAL", b.addVec3(normals)}}},
                                {"indices", b.addIndices(indices)},
                                {"material", material}});
    b.setScene({b.addNode({{"mesh", mesh}})});
    const std::string path = dir.file("box.gltf");
    b.writeGltf(path);
    return path;
}

// Mean luminance right of the image's centre over left of it, where the box's sides are: the
// middle half of the columns, the lower half of the rows (the top face is above).
double rightOverLeft(const Image& image) {
    double left = 0.0, right = 0.0;
    for (int y = image.height / 2; y < image.height; ++y)
        for (int x = image.width / 4; x < 3 * image.width / 4; ++x) {
            const glm::vec3 c = image.at(x, y);
            (2 * x < image.width ? left : right) += 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        }
    return right / left;
}

TEST(EnvironmentOptions, RotationTurnsTheLightAlikeInTheGlslViewAndThePathTracer) {
    TempDir dir;
    const std::string box = turnedBox(dir), sky = skyWithAWindow(dir);
    // Turned -45 degrees the window faces the right face; turned -135 the left one (a rotation
    // of the wrong sign would light neither, a mirrored one the other).
    for (const auto& [degrees, rightLit] : {std::pair{-45, true}, std::pair{-135, false}}) {
        const std::string light = " --width 64 --height 48 --environment " + sky + " --environment-intensity 4 --environment-rotation " +
                                  std::to_string(degrees);
        const std::string glsl = dir.file("glsl" + std::to_string(-degrees) + ".exr");
        const std::string traced = dir.file("traced" + std::to_string(-degrees) + ".exr");
        ASSERT_EQ(test::runWovenWithErrors("preview " + box + light + " --headless --screenshot " + glsl), 0);
        ASSERT_EQ(test::runWovenWithErrors("preview " + box + light + " --headless --viewport rendered --passes 16 --no-denoise --screenshot " + traced), 0);
        for (const std::string& file : {glsl, traced}) {
            const double ratio = rightOverLeft(readExr(file).image);

            if (rightLit) EXPECT_GT(ratio, 1.5) << file << " at " << degrees << " degrees";
            else EXPECT_LT(ratio, 1.0 / 1.5) << file << " at " << degrees << " degrees";
        }
    }
}

TEST(EnvironmentOptions, BadValuesNameTheOption) {
    TempDir dir;
    std::string errors;
    EXPECT_NE(test::runWovenWithErrors("render " + kScene + kFrame + " --environment-intensity -1 -o " + dir.file("a.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-intensity"));
    EXPECT_NE(test::runWovenWithErrors("render " + kScene + kFrame + " --environment-rotation nan -o " + dir.file("b.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-rotation"));
    EXPECT_NE(test::runWovenWithErrors("render " + kScene + kFrame + " --environment 5000 --environment-intensity 1e6 -o " + dir.file("c.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-intensity: times the environment's colour is"));
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.exr")) || std::filesystem::exists(dir.file("b.exr")) ||
                 std::filesystem::exists(dir.file("c.exr")));
}

}  // namespace
}  // namespace woven
