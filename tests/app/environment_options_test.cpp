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
#include "../scene/temp_dir.h"
#include "display_transform.h"
#include "frame_io.h"

namespace woven {
namespace {

using test::TempDir;

int run(const std::string& args, std::string* errors = nullptr) {
    const std::string errorFile = testing::TempDir() + "woven_environment_options_stderr_" + std::to_string(::getpid()) + ".txt";
    const int status = test::runWoven(args + " 2>" + errorFile).exitCode;
    if (errors) {
        std::ifstream in(errorFile);
        *errors = std::string(std::istreambuf_iterator<char>(in), {});
    }
    std::remove(errorFile.c_str());
    return status;
}

const std::string kScene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
const std::string kFrame = " --width 32 --height 24 --spp 2 --integrator path --no-denoise --noise-threshold 0";

Image render(const TempDir& dir, const std::string& name, const std::string& options) {
    const std::string path = dir.file(name + ".exr");
    EXPECT_EQ(run("render " + kScene + kFrame + " " + options + " -o " + path), 0) << options;
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

TEST(EnvironmentOptions, RotationTurnsAnImage) {
    TempDir dir;
    // A dim sky with one bright window towards +x.
    Image sky;
    sky.width = 32;
    sky.height = 16;
    sky.pixels.assign(size_t(sky.width) * sky.height, glm::vec3(0.05f));
    for (int y = 3; y < 8; ++y)
        for (int x = 6; x < 10; ++x) sky.at(x, y) = glm::vec3(1.0f);
    const std::string file = dir.file("sky.png");
    writePng(file, sky, {0.0f, ToneMap::Clamp});
    const Image unturned = render(dir, "a", "--environment " + file);
    EXPECT_TRUE(render(dir, "b", "--environment " + file + " --environment-rotation 0").pixels == unturned.pixels);
    EXPECT_FALSE(render(dir, "c", "--environment " + file + " --environment-rotation 90").pixels == unturned.pixels);
}

TEST(EnvironmentOptions, BadValuesNameTheOption) {
    TempDir dir;
    std::string errors;
    EXPECT_NE(run("render " + kScene + kFrame + " --environment-intensity -1 -o " + dir.file("a.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-intensity"));
    EXPECT_NE(run("render " + kScene + kFrame + " --environment-rotation nan -o " + dir.file("b.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-rotation"));
    EXPECT_NE(run("render " + kScene + kFrame + " --environment 5000 --environment-intensity 1e6 -o " + dir.file("c.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--environment-intensity: times the environment's colour is"));
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.exr")) || std::filesystem::exists(dir.file("b.exr")) ||
                 std::filesystem::exists(dir.file("c.exr")));
}

}  // namespace
}  // namespace woven
