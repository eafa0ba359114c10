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

#include "exr_file.h"
#include "frame_io.h"
#include "image_checks.h"
#include "image_io.h"
#include "render_passes.h"
#include "../common/run_woven.h"

namespace {

namespace fs = std::filesystem;

using Result = woven::test::RunResult;
Result run(const std::string& args) { return woven::test::runWovenCommand(args); }

class MergeCommand : public woven::test::CommandTest {
protected:
    // Samples [first, first + spp) of a small BDPT frame (splats and camera paths both), or of
    // the frame `options` say.
    std::string render(const std::string& name, int64_t first, int spp,
                       const std::string& options = "--width 48 --height 36 --seed 11 --integrator bdpt") {
        const std::string path = file(name);
        const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
        EXPECT_EQ(run("render " + scene + " " + options + " --first-sample " + std::to_string(first) + " --spp " +
                      std::to_string(spp) + " -o " + path)
                      .exitCode,
                  0);
        return path;
    }
};

TEST_F(MergeCommand, DisjointRangesMergeToTheUnionBitForBit) {
    const std::string a = render("a.exr", 0, 2), b = render("b.exr", 2, 3), c = render("c.exr", 5, 1);
    const std::string all = render("all.exr", 0, 6);
    ASSERT_EQ(run("merge " + c + " " + a + " " + b + " --expect-samples 6 -o " + file("merged.exr")).exitCode, 0);

    const woven::ExrImage m = woven::readExr(file("merged.exr")), u = woven::readExr(all);
    ASSERT_EQ(m.image.pixels.size(), u.image.pixels.size());
    EXPECT_EQ(m.sampleCount, std::vector<float>(u.image.pixels.size(), 6.0f));
    EXPECT_EQ(m.sampleSums, u.sampleSums);
    // The render passes too: their sums, and so the layers compositors read.
    ASSERT_EQ(u.passSums.size(), u.image.pixels.size());
    EXPECT_EQ(m.passSums, u.passSums);
    ASSERT_TRUE(m.samples);
    EXPECT_EQ(m.samples->first, 0);
    EXPECT_EQ(m.samples->count, 6);
    const woven::RenderPasses mp = m.passes(), up = u.passes();
    double mean = 0.0, depth = 0.0;
    for (size_t i = 0; i < u.image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(m.image.pixels[i][c], u.image.pixels[i][c]) << "pixel " << i;
        ASSERT_EQ(mp.albedo.pixels[i], up.albedo.pixels[i]) << "pixel " << i;
        ASSERT_EQ(mp.normal.pixels[i], up.normal.pixels[i]) << "pixel " << i;
        ASSERT_EQ(mp.depth[i], up.depth[i]) << "pixel " << i;
        ASSERT_EQ(mp.variance.pixels[i], up.variance.pixels[i]) << "pixel " << i;
        mean += u.image.pixels[i].r;
        depth += up.depth[i];
    }
    EXPECT_GT(mean, 0.0);
    EXPECT_GT(depth, 0.0);

    // A merged frame merges again, exactly: ranges of ranges.
    const std::string d = render("d.exr", 6, 2);
    ASSERT_EQ(run("merge " + file("merged.exr") + " " + d + " -o " + file("again.exr")).exitCode, 0);
    EXPECT_EQ(woven::readExr(file("again.exr")).sampleSums, woven::readExr(render("all8.exr", 0, 8)).sampleSums);
}

// Parts of the layout before render passes (32-bit unsigned sums sum.R0-sum.B3, count N) merge
// as they did, into a frame without passes, said in a warning; with parts that have passes
// they are refused by name.
TEST_F(MergeCommand, PartsOfTheOlderLayoutMergeWithoutPasses) {
    const std::string paths[] = {render("a.exr", 0, 2), render("b.exr", 2, 1)};
    const auto writeOld = [&](const std::string& path, const std::string& to) {
        const woven::ExrImage part = woven::readExr(path);
        woven::ExrFile old;
        old.width = part.image.width;
        old.height = part.image.height;
        const size_t count = part.image.pixels.size();
        for (int c = 0; c < 3; ++c) {
            woven::ExrChannel& colour = old.channels.emplace_back(woven::ExrChannel{std::string(1, "RGB"[c]), woven::ExrChannelType::Float, {}, {}});
            for (const glm::vec3& p : part.image.pixels) colour.values.push_back(p[c]);
            for (int w = 0; w < 4; ++w) {
                woven::ExrChannel sum{std::string("sum.") + "RGB"[c] + std::to_string(w), woven::ExrChannelType::Uint, {}, {}};
                for (size_t i = 0; i < count; ++i) sum.words.push_back(part.sampleSums[3 * i + size_t(c)].words()[size_t(w)]);
                old.channels.push_back(std::move(sum));
            }
        }
        old.channels.push_back({"N", woven::ExrChannelType::Float, part.sampleCount, {}});
        old.attributes = {{"wovenFirstSample", std::to_string(part.samples->first)},
                          {"wovenSampleCount", std::to_string(part.samples->count)}};
        woven::writeExrFile(to, old);
    };
    writeOld(paths[0], file("old_a.exr"));
    writeOld(paths[1], file("old_b.exr"));
    Result r = run("merge " + file("old_a.exr") + " " + file("old_b.exr") + " -o " + file("old.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, testing::HasSubstr("warning: " + file("old_a.exr") + " has no render passes"));
    const woven::ExrImage merged = woven::readExr(file("old.exr")), all = woven::readExr(render("all.exr", 0, 3));
    EXPECT_EQ(merged.sampleSums, all.sampleSums);
    // Without passes there is nothing to denoise by: the merged beauty is the noisy mean.
    ASSERT_TRUE(all.noisy);
    EXPECT_EQ(merged.image.pixels, all.noisy->pixels);
    EXPECT_FALSE(merged.noisy);
    EXPECT_TRUE(merged.passSums.empty());

    r = run("merge " + paths[0] + " " + file("old_b.exr") + " -o " + file("mixed.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr(file("old_b.exr") + " has no render passes (rendered with --no-passes, or by an older woven) and " +
                                          paths[0] + " has"));
    EXPECT_FALSE(fs::exists(file("mixed.exr")));
}

// Parts of a woven before the direct-light pass (render passes without exact.direct*) merge with
// each other into a frame without it; with parts that have it they are refused by name.
TEST_F(MergeCommand, PartsWithoutTheDirectLightPassMergeWithEachOther) {
    const std::string a = render("a.exr", 0, 2), b = render("b.exr", 2, 1);
    ASSERT_FALSE(woven::readExr(a).lacksDirectPass);
    for (const std::string& path : {a, b}) {
        woven::ExrImage part = woven::readExr(path);
        for (woven::PassSums& p : part.passSums)
            for (woven::ExactSum& d : p.direct) d = woven::ExactSum();
        part.lacksDirectPass = true;
        woven::writeExr(file("old_" + fs::path(path).filename().string()), part, woven::ExrPrecision::Float);
    }
    const std::string oldA = file("old_a.exr"), oldB = file("old_b.exr");
    {
        const std::vector<unsigned char> bytes = woven::readImageFile(oldA);
        for (const woven::ExrChannel& c : woven::readExrFile(bytes.data(), bytes.size(), oldA).channels)
            EXPECT_EQ(c.name.find("direct"), std::string::npos) << c.name;
    }
    Result r = run("merge " + oldA + " " + oldB + " -o " + file("old.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const woven::ExrImage merged = woven::readExr(file("old.exr")), all = woven::readExr(render("all.exr", 0, 3));
    EXPECT_TRUE(merged.lacksDirectPass);
    EXPECT_EQ(merged.sampleSums, all.sampleSums);
    ASSERT_EQ(merged.passSums.size(), all.passSums.size());
    for (size_t i = 0; i < all.passSums.size(); ++i) {
        ASSERT_EQ(merged.passSums[i].albedo[0], all.passSums[i].albedo[0]) << "pixel " << i;
        ASSERT_EQ(merged.passSums[i].square[2], all.passSums[i].square[2]) << "pixel " << i;
    }

    r = run("merge " + a + " " + oldB + " -o " + file("mixed.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr(oldB + " has no direct-light pass (an older woven wrote it) and " + a + " has"));
    EXPECT_FALSE(fs::exists(file("mixed.exr")));
}

TEST_F(MergeCommand, MissingSamplesAreNamedAndGoToThePartialFrame) {
    const std::string a = render("a.exr", 0, 2), c = render("c.exr", 5, 1);
    const Result r = run("merge " + a + " " + c + " --expect-samples 8 -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("frame.exr not written: samples 2-4, 6-7 missing"));
    EXPECT_THAT(r.out, testing::HasSubstr("frame.partial.exr from samples 0-1, 5"));
    EXPECT_FALSE(fs::exists(file("frame.exr")));
    const woven::ExrImage partial = woven::readExr(file("frame.partial.exr"));
    EXPECT_EQ(partial.sampleCount.front(), 3.0f);
    EXPECT_FALSE(partial.samples) << "samples 0-1 and 5 are no one range";

    // Once the rest is there, the frame is written and the stale partial frame goes.
    const std::string b = render("b.exr", 2, 3), d = render("d.exr", 6, 2);
    ASSERT_EQ(run("merge " + a + " " + b + " " + c + " " + d + " --expect-samples 8 -o " + file("frame.exr")).exitCode, 0);
    EXPECT_TRUE(fs::exists(file("frame.exr")));
    EXPECT_FALSE(fs::exists(file("frame.partial.exr")));
}

TEST_F(MergeCommand, OverlapsAndStrangersAreRefusedAndWriteNothing) {
    const std::string a = render("a.exr", 0, 3), b = render("b.exr", 2, 2);
    Result r = run("merge " + a + " " + b + " -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("(samples 0-2) and " + b + " (samples 2-3) overlap"));

    r = run("merge " + a + " --expect-samples 2 -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("holds samples 0-2, beyond the 2 expected"));

    // A file without sample sums (a PNG, or an EXR of another tool) cannot be merged.
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    ASSERT_EQ(run("render " + scene + " --width 48 --height 36 --spp 1 -o " + file("c.png")).exitCode, 0);
    r = run("merge " + a + " " + file("c.png") + " -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("c.png"));

    r = run("merge --expect-samples 4 -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("no part files, samples 0-3 missing"));
    EXPECT_FALSE(fs::exists(file("frame.exr")));
    EXPECT_FALSE(fs::exists(file("frame.partial.exr")));
}

// Sample indices are 64-bit: ranges past 2^31 overlap, abut and merge as any others (a 32-bit end
// wrapped to a negative number, so parts that overlapped merged and counted samples twice).
const std::string kSmall = "--width 12 --height 9 --seed 11 --integrator bdpt";

TEST_F(MergeCommand, RangesPast32BitsAreCheckedAndMergeBitForBit) {
    const int64_t base = 2147483646;
    const std::string a = render("a.exr", base, 2, kSmall);
    const std::string b = render("b.exr", base + 1, 2, kSmall);
    Result r = run("merge " + a + " " + b + " -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("(samples 2147483646-2147483647) and " + b +
                                             " (samples 2147483647-2147483648) overlap"));
    EXPECT_FALSE(fs::exists(file("frame.exr")));

    const std::string c = render("c.exr", base + 2, 1, kSmall);
    ASSERT_EQ(run("merge " + a + " " + c + " -o " + file("frame.exr")).exitCode, 0);
    const woven::ExrImage m = woven::readExr(file("frame.exr"));
    const woven::ExrImage u = woven::readExr(render("all.exr", base, 3, kSmall));
    ASSERT_TRUE(m.samples);
    EXPECT_EQ(m.samples->first, base);
    EXPECT_EQ(m.samples->count, 3);
    EXPECT_EQ(m.sampleSums, u.sampleSums);
    EXPECT_EQ(m.sampleCount, std::vector<float>(m.sampleCount.size(), 3.0f));

    // Past 2^32 too; beyond 2^62 (where the auto integrator's pilot samples) the option is named.
    const woven::ExrImage far = woven::readExr(render("far.exr", 4294967295, 1, kSmall));
    ASSERT_TRUE(far.samples);
    EXPECT_EQ(far.samples->first, 4294967295);
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    r = run("render " + scene + " --width 12 --height 9 --first-sample 4611686018427387904 -o " + file("x.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("--first-sample: '4611686018427387904' is outside the range: it must be from 0 to"));
    r = run("render " + scene + " --width 12 --height 9 --first-sample 4611686018427387900 --spp 5 -o " + file("x.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, testing::HasSubstr("--first-sample 4611686018427387900 with --spp 5 ends past sample index 2^62"));
    EXPECT_FALSE(fs::exists(file("x.exr")));
}

// Parts record the frame they are of: a different seed, integrator, depth, weave filter, sampler or
// scene (here a material changed by --woven) is refused, naming both files and what differs.
TEST_F(MergeCommand, PartsOfDifferentFramesAreRefusedNamingWhatDiffers) {
    const std::string a = render("a.exr", 0, 1, kSmall);
    const std::pair<const char*, const char*> others[] = {
        {"--width 12 --height 9 --seed 12 --integrator bdpt", "--seed 11 in "},
        {"--width 12 --height 9 --seed 11 --integrator path", "--integrator bdpt in "},
        {"--width 12 --height 9 --seed 11 --integrator bdpt --max-depth 3", "--max-depth 8 in "},
        {"--width 12 --height 9 --seed 11 --integrator bdpt --filter", "--filter off in "},
        {"--width 12 --height 9 --seed 11 --integrator bdpt --sampler independent", "--sampler sobol in "},
        {"--width 12 --height 9 --seed 11 --integrator bdpt --woven 'Cloth={\"weft_color\": [0.9, 0.1, 0.1]}'",
         "the scene (with its camera and materials) has the hash "},
    };
    for (const auto& [options, difference] : others) {
        const std::string b = render("b.exr", 1, 1, options);
        const Result r = run("merge " + a + " " + b + " -o " + file("frame.exr"));
        EXPECT_NE(r.exitCode, 0) << options;
        EXPECT_THAT(r.out, testing::HasSubstr(a + " and " + b + " are parts of different frames: " + difference))
            << options;
        EXPECT_FALSE(fs::exists(file("frame.exr"))) << options;
    }
    // What only decides how many samples a pixel takes may differ (woven submit gives each task
    // its own noise threshold).
    const std::string b = render("b.exr", 1, 2, kSmall + " --noise-threshold 0.3");
    const Result r = run("merge " + a + " " + b + " -o " + file("frame.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    ASSERT_TRUE(woven::readExr(file("frame.exr")).frame);
    EXPECT_EQ(woven::readExr(file("frame.exr")).frame->seed, 11u);
}

// Parts written before parts recorded their frame merge as they did, with one warning; the merge
// records no frame then. Parts whose --integrator auto chose differently merge, said in a note.
TEST_F(MergeCommand, PartsWithoutAnIdentityMergeWithOneWarning) {
    const std::string a = render("a.exr", 0, 1, kSmall), b = render("b.exr", 1, 1, kSmall), c = render("c.exr", 2, 1, kSmall);
    for (const std::string& path : {b, c}) {
        woven::ExrImage old = woven::readExr(path);
        old.frame.reset();
        woven::writeExr(path, old, woven::ExrPrecision::Float);
    }
    Result r = run("merge " + a + " " + b + " " + c + " -o " + file("frame.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, testing::HasSubstr("warning: " + b + " and 1 more record no scene, seed or integrator"));
    EXPECT_EQ(r.out.find("warning:"), r.out.rfind("warning:")) << r.out;
    EXPECT_FALSE(woven::readExr(file("frame.exr")).frame);

    const std::string picks[] = {"auto: path", "auto: bdpt"};
    for (int i = 0; i < 2; ++i) {
        woven::ExrImage part = woven::readExr(i == 0 ? a : b);
        part.frame = woven::readExr(a).frame;
        part.frame->integrator = picks[i];
        woven::writeExr(i == 0 ? a : b, part, woven::ExrPrecision::Float);
    }
    r = run("merge " + a + " " + b + " -o " + file("auto.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, testing::HasSubstr("note: --integrator auto chose differently"));
    ASSERT_TRUE(woven::readExr(file("auto.exr")).frame);
    EXPECT_EQ(woven::readExr(file("auto.exr")).frame->integrator, "auto");
}

}  // namespace
