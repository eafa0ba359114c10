// `woven merge` of disjoint sample ranges equals the render of their union bit for bit: the
// property that lets a Slurm job array split one frame over machines. With --expect-samples it
// refuses to write a frame that misses samples, names them and writes OUT.partial.exr instead.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "image_io.h"
#include "woven_command.h"

namespace {

namespace fs = std::filesystem;

using Result = woven::test::CommandResult;
Result run(const std::string& args) { return woven::test::runWovenCommand(args); }

class MergeCommand : public woven::test::CommandTest {
protected:
    // Samples [first, first + spp) of a small BDPT frame (splats and camera paths both).
    std::string render(const std::string& name, int first, int spp) {
        const std::string path = file(name);
        const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
        EXPECT_EQ(run("render " + scene + " --width 48 --height 36 --seed 11 --integrator bdpt --first-sample " +
                      std::to_string(first) + " --spp " + std::to_string(spp) + " -o " + path)
                      .status,
                  0);
        return path;
    }
};

TEST_F(MergeCommand, DisjointRangesMergeToTheUnionBitForBit) {
    const std::string a = render("a.exr", 0, 2), b = render("b.exr", 2, 3), c = render("c.exr", 5, 1);
    const std::string all = render("all.exr", 0, 6);
    ASSERT_EQ(run("merge " + c + " " + a + " " + b + " --expect-samples 6 -o " + file("merged.exr")).status, 0);

    const woven::ExrImage m = woven::readExr(file("merged.exr")), u = woven::readExr(all);
    ASSERT_EQ(m.image.pixels.size(), u.image.pixels.size());
    EXPECT_EQ(m.sampleCount, std::vector<float>(u.image.pixels.size(), 6.0f));
    EXPECT_EQ(m.sampleSums, u.sampleSums);
    ASSERT_TRUE(m.samples);
    EXPECT_EQ(m.samples->first, 0);
    EXPECT_EQ(m.samples->count, 6);
    double mean = 0.0;
    for (size_t i = 0; i < u.image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(m.image.pixels[i][c], u.image.pixels[i][c]) << "pixel " << i;
        mean += u.image.pixels[i].r;
    }
    EXPECT_GT(mean, 0.0);

    // A merged frame merges again, exactly: ranges of ranges.
    const std::string d = render("d.exr", 6, 2);
    ASSERT_EQ(run("merge " + file("merged.exr") + " " + d + " -o " + file("again.exr")).status, 0);
    EXPECT_EQ(woven::readExr(file("again.exr")).sampleSums, woven::readExr(render("all8.exr", 0, 8)).sampleSums);
}

TEST_F(MergeCommand, MissingSamplesAreNamedAndGoToThePartialFrame) {
    const std::string a = render("a.exr", 0, 2), c = render("c.exr", 5, 1);
    const Result r = run("merge " + a + " " + c + " --expect-samples 8 -o " + file("frame.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.output, testing::HasSubstr("frame.exr not written: samples 2-4, 6-7 missing"));
    EXPECT_THAT(r.output, testing::HasSubstr("frame.partial.exr from samples 0-1, 5"));
    EXPECT_FALSE(fs::exists(file("frame.exr")));
    const woven::ExrImage partial = woven::readExr(file("frame.partial.exr"));
    EXPECT_EQ(partial.sampleCount.front(), 3.0f);
    EXPECT_FALSE(partial.samples) << "samples 0-1 and 5 are no one range";

    // Once the rest is there, the frame is written and the stale partial frame goes.
    const std::string b = render("b.exr", 2, 3), d = render("d.exr", 6, 2);
    ASSERT_EQ(run("merge " + a + " " + b + " " + c + " " + d + " --expect-samples 8 -o " + file("frame.exr")).status, 0);
    EXPECT_TRUE(fs::exists(file("frame.exr")));
    EXPECT_FALSE(fs::exists(file("frame.partial.exr")));
}

TEST_F(MergeCommand, OverlapsAndStrangersAreRefusedAndWriteNothing) {
    const std::string a = render("a.exr", 0, 3), b = render("b.exr", 2, 2);
    Result r = run("merge " + a + " " + b + " -o " + file("frame.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.output, testing::HasSubstr("(samples 0-2) and " + b + " (samples 2-3) overlap"));

    r = run("merge " + a + " --expect-samples 2 -o " + file("frame.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.output, testing::HasSubstr("holds samples 0-2, beyond the 2 expected"));

    // A file without sample sums (a PNG, or an EXR of another tool) cannot be merged.
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    ASSERT_EQ(run("render " + scene + " --width 48 --height 36 --spp 1 -o " + file("c.png")).status, 0);
    r = run("merge " + a + " " + file("c.png") + " -o " + file("frame.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.output, testing::HasSubstr("c.png"));

    r = run("merge --expect-samples 4 -o " + file("frame.exr"));
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.output, testing::HasSubstr("no part files, samples 0-3 missing"));
    EXPECT_FALSE(fs::exists(file("frame.exr")));
    EXPECT_FALSE(fs::exists(file("frame.partial.exr")));
}

}  // namespace
