// What a user can type that asks too much or means nothing: more threads than any machine has,
// a frame that cannot fit in memory, a pattern of 10^10 cells, an exposure of 10^39 stops, an
// output folder that does not exist, and merges of parts that cannot add up. Each gets a clear
// message (or, for threads, a warning and the hardware's count), before any long work, and
// leaves no file behind; a run killed outright leaves a temporary file that the next write of
// the same name removes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "frame_io.h"
#include "image_io.h"
#include "../common/run_woven.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using Result = woven::test::RunResult;
Result run(const std::string& args) { return woven::test::runWovenCommand(args); }

class UntrustedCommands : public woven::test::CommandTest {
protected:
    const std::string scene_ = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    std::string render(const std::string& name, int first, int spp) {
        EXPECT_EQ(run("render " + scene_ + " --width 16 --height 12 --integrator path --noise-threshold 0 --first-sample " +
                      std::to_string(first) + " --spp " + std::to_string(spp) + " -o " + file(name))
                      .exitCode,
                  0);
        return file(name);
    }
};

TEST_F(UntrustedCommands, MoreThreadsThanTheMachineHasAreCappedWithAWarning) {
    const Result r = run("render " + scene_ + " --width 16 --height 12 --spp 1 --threads 100000 -o " + file("t.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("warning: --threads 100000"));
    EXPECT_TRUE(fs::exists(file("t.exr")));
}

TEST_F(UntrustedCommands, AFrameTooLargeForMemoryIsRefusedBeforeRendering) {
    const Result r = run("render " + scene_ + " --width 32768 --height 32768 --spp 1 -o " + file("big.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("32768 x 32768 frame needs about"));
    EXPECT_THAT(r.out, ::testing::Not(HasSubstr("bad_alloc")));
    EXPECT_FALSE(fs::exists(file("big.exr")));
}

TEST_F(UntrustedCommands, APatternTooLargeToPrintOrDrawIsRefused) {
    Result r = run("pattern --size 100000,100000");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("--size 100000,100000"));
    r = run("pattern --size 100000,100000 --png " + file("p.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("more than woven draws"));
    EXPECT_FALSE(fs::exists(file("p.png")));
    // Within a side but past the pixel limit: the command's own message, naming the option, with
    // the drawdown image's limit (2^24), not the drawing code's.
    r = run("pattern --pattern 1,1,1 --size 8192,8192 --cell-pixels 1 --png " + file("p.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("--size 8192,8192 at --cell-pixels 1"));
    EXPECT_THAT(r.out, HasSubstr("16777216 pixels"));
    EXPECT_FALSE(fs::exists(file("p.png")));
}

TEST_F(UntrustedCommands, AnExposureBeyondAnyDisplayIsRefused) {
    const Result r = run("render " + scene_ + " --width 16 --height 12 --spp 1 --exposure 1e39 -o " + file("e.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("--exposure"));
    EXPECT_FALSE(fs::exists(file("e.png")));
}

TEST_F(UntrustedCommands, AnUnwritableOutputIsFoundBeforeRendering) {
    // 10^6 spp would take hours: the command must fail at once, not after the render.
    Result r = run("render " + scene_ + " --spp 1000000 -o " + file("no/such/folder/out.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("no/such/folder/out.exr: cannot write in the folder"));
    fs::create_directory(file("dir.exr"));
    r = run("render " + scene_ + " --spp 1000000 -o " + file("dir.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("is a directory"));
}

TEST_F(UntrustedCommands, AStaleTemporaryFileOfAKilledRunIsRemovedByTheNextWrite) {
    char host[HOST_NAME_MAX + 1] = {};
    ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
    // A PID above any pid_max (2^22): no process has it.
    const std::string stale = file("s.exr.tmp-" + std::string(host) + "-99999999");
    std::ofstream(stale) << "half a frame";
    render("s.exr", 0, 1);
    EXPECT_TRUE(fs::exists(file("s.exr")));
    EXPECT_FALSE(fs::exists(stale));
}

TEST_F(UntrustedCommands, MergeRefusesWhatCannotAddUp) {
    const std::string a = render("a.exr", 0, 1), b = render("b.exr", 1, 1);
    // The output must say EXR: merge writes nothing else.
    Result r = run("merge " + a + " " + b + " -o " + file("frame.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("must end in .exr"));
    EXPECT_FALSE(fs::exists(file("frame.png")));
    // The same part twice would count its samples twice, also under another name.
    fs::create_symlink(a, file("a_again.exr"));
    r = run("merge " + a + " " + file("a_again.exr") + " -o " + file("frame.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("are the same file"));
    // A part as the output would be replaced by the merge.
    r = run("merge " + a + " " + b + " -o " + b);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("is both a part and the output"));
    // Sample counts that are no count: negative, NaN, past the part's one sample, not whole, and 0
    // beside a sum (the merged pixel would be divided by the other part's count alone).
    for (float n : {-1.0f, std::numeric_limits<float>::quiet_NaN(), 1e30f, 0.5f, 0.0f}) {
        woven::ExrImage part = woven::readExr(b);
        part.sampleCount[3] = n;
        woven::writeExr(file("bad.exr"), part);
        r = run("merge " + a + " " + file("bad.exr") + " -o " + file("frame.exr"));
        EXPECT_NE(r.exitCode, 0) << n;
        EXPECT_THAT(r.out, HasSubstr("bad.exr: pixel (3, 0) has the sample count N")) << n;
    }
    EXPECT_FALSE(fs::exists(file("frame.exr")));
}

}  // namespace
