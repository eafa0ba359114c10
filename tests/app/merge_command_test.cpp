// `woven merge` of two disjoint sample ranges equals the render of their union: the property
// that lets a Slurm job array split one frame over machines.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "image_io.h"

namespace {

int run(const std::string& args) {
    const std::string cmd = std::string(WOVEN_BINARY) + " " + args + " 2>/dev/null";
    return std::system(cmd.c_str());
}

TEST(MergeCommand, DisjointRangesMergeToTheUnion) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("woven_merge_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    const std::string common = " --width 48 --height 36 --seed 11 --integrator bdpt";
    const std::string a = (dir / "a.exr").string(), b = (dir / "b.exr").string();
    const std::string all = (dir / "all.exr").string(), merged = (dir / "merged.exr").string();
    ASSERT_EQ(run("render " + scene + common + " --spp 2 -o " + a), 0);
    ASSERT_EQ(run("render " + scene + common + " --spp 3 --first-sample 2 -o " + b), 0);
    ASSERT_EQ(run("render " + scene + common + " --spp 5 -o " + all), 0);
    ASSERT_EQ(run("merge " + a + " " + b + " -o " + merged), 0);

    const woven::ExrImage m = woven::readExr(merged), u = woven::readExr(all);
    ASSERT_EQ(m.image.pixels.size(), u.image.pixels.size());
    double maxDiff = 0.0, mean = 0.0;
    for (size_t i = 0; i < u.image.pixels.size(); ++i) {
        EXPECT_EQ(m.sampleCount[i], 5.0f);
        for (int c = 0; c < 3; ++c) {
            maxDiff = std::max(maxDiff, double(std::abs(m.image.pixels[i][c] - u.image.pixels[i][c])));
            mean += u.image.pixels[i][c];
        }
    }
    mean /= 3.0 * u.image.pixels.size();
    ASSERT_GT(mean, 0.0);
    // Only float summation order differs between the two: 1e-5 of the mean image value.
    EXPECT_LT(maxDiff, 1e-5 * std::max(1.0, mean));

    // A file without sample counts cannot be merged: a clear error, no output.
    const std::string png = (dir / "c.png").string(), bad = (dir / "bad.exr").string();
    ASSERT_EQ(run("render " + scene + common + " --spp 1 -o " + png), 0);
    EXPECT_NE(run("merge " + a + " " + png + " -o " + bad), 0);
    EXPECT_FALSE(fs::exists(bad));
    fs::remove_all(dir);
}

}  // namespace
