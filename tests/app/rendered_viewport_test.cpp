// The window's Rendered mode headless (`woven preview --headless --viewport rendered --passes N`,
// the window's code path: RenderedViewport at the preview's initial camera) against
// `woven render --spp N --noise-threshold 0`: undenoised, the same frame bit for bit, since the
// view's passes are the same RenderJob's over the same sample range.
#include <gtest/gtest.h>
#include <unistd.h>

#include <gmock/gmock.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "../common/run_woven.h"
#include "../scene/temp_dir.h"
#include "frame_io.h"

namespace woven {
namespace {

using test::TempDir;

const std::string kScene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
const std::string kFrame = " --width 64 --height 48 --seed 5";

TEST(RenderedViewCommand, UndenoisedFrameAfterNPassesIsWovenRendersOfNSamplesBitForBit) {
    TempDir dir;
    const std::string rendered = dir.file("render.exr"), view = dir.file("view.exr");
    // The view renders with the path tracer where the scene leaves the integrator to auto.
    ASSERT_EQ(test::runWovenWithErrors("render " + kScene + kFrame + " --spp 4 --noise-threshold 0 --no-denoise --integrator path -o " + rendered), 0);
    ASSERT_EQ(test::runWovenWithErrors("preview " + kScene + kFrame + " --headless --viewport rendered --passes 4 --no-denoise --screenshot " + view), 0);
    const ExrImage a = readExr(rendered), b = readExr(view);
    ASSERT_EQ(b.image.width, 64);
    ASSERT_EQ(b.image.height, 48);
    EXPECT_TRUE(a.image.pixels == b.image.pixels) << "the view's radiance differs from woven render's";
    EXPECT_EQ(a.sampleCount, b.sampleCount);
    EXPECT_EQ(b.sampleCount.front(), 4.0f);
    EXPECT_TRUE(a.sampleSums == b.sampleSums);
    EXPECT_TRUE(a.passSums == b.passSums);
    EXPECT_FALSE(b.noisy.has_value());
}

TEST(RenderedViewCommand, DenoisedFrameKeepsTheRunningMeanBeside) {
    TempDir dir;
    const std::string rendered = dir.file("render.exr"), view = dir.file("view.exr");
    ASSERT_EQ(test::runWovenWithErrors("render " + kScene + kFrame + " --spp 3 --noise-threshold 0 --no-denoise --integrator path -o " + rendered), 0);
    ASSERT_EQ(test::runWovenWithErrors("preview " + kScene + kFrame + " --headless --viewport rendered --passes 3 --screenshot " + view), 0);
    const ExrImage a = readExr(rendered), b = readExr(view);
    ASSERT_TRUE(b.noisy.has_value()) << "the last pass is denoised";
    EXPECT_TRUE(b.noisy->pixels == a.image.pixels);
    EXPECT_FALSE(b.image.pixels == a.image.pixels);
}

TEST(RenderedViewCommand, MisplacedOptionsAreRefusedByName) {
    TempDir dir;
    std::string errors;
    EXPECT_NE(test::runWovenWithErrors("preview " + kScene + " --headless --passes 2 --screenshot " + dir.file("a.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--passes"));
    EXPECT_THAT(errors, testing::HasSubstr("--viewport rendered"));
    EXPECT_NE(test::runWovenWithErrors("preview " + kScene + " --headless --final --viewport rendered --screenshot " + dir.file("b.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--final"));
    EXPECT_NE(test::runWovenWithErrors("preview " + kScene + " --headless --viewport raytraced --screenshot " + dir.file("c.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--viewport"));
    EXPECT_NE(test::runWovenWithErrors("preview " + kScene + " --headless --viewport rendered --passes 0 --screenshot " + dir.file("d.exr"), &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--passes"));
    // The window's count of passes is --spp: --passes is the headless frame's alone.
    EXPECT_NE(test::runWovenWithErrors("preview " + kScene + " --viewport rendered --passes 2", &errors), 0);
    EXPECT_THAT(errors, testing::HasSubstr("--passes is for --headless"));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace woven
