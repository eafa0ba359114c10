// `woven submit` without a cluster: --dry-run writes the job scripts, and running them by hand
// as Slurm would (SLURM_ARRAY_TASK_ID set) renders the frame a local render gives, bit for bit,
// whatever spaces and quotes the paths and options hold. Bad requests fail before anything is
// submitted. slurm_cluster_test.sh runs the same on a real cluster.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/run_woven.h"
#include "../scene/temp_dir.h"
#include "frame_pattern.h"
#include "frame_io.h"
#include "image_io.h"
#include "shell_quote.h"

namespace woven {
namespace {

using test::TempDir;
namespace fs = std::filesystem;

struct Result {
    int status;
    std::string output;  // stdout, then stderr
};

Result shell(const std::string& command) {
    Result result{-1, ""};
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
    result.status = pclose(pipe);
    return result;
}

Result woven(const std::vector<std::string>& args) {
    const test::RunResult r = test::runWovenCommand(shellCommand(args));
    return {r.exitCode, r.out};
}

// A scene file in `folder` that loads the bundled cloth, under a sky of this colour.
std::string writeScene(const fs::path& path, float sky) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << R"({"gltf": ")" << WOVEN_ASSETS_DIR << R"(/cloth_drape.glb", "environment": {"color": [)"
                        << sky << ", " << sky << ", " << sky << "]}}";
    return path.string();
}

void expectSameFrame(const std::string& a, const std::string& b) {
    const ExrImage x = readExr(a), y = readExr(b);
    EXPECT_TRUE(x.image.pixels == y.image.pixels) << a << " and " << b << " differ";
    EXPECT_EQ(x.sampleCount, y.sampleCount);
    EXPECT_EQ(x.sampleSums, y.sampleSums);
}

TEST(ShellQuote, BashReadsBackTheSameBytes) {
    for (const std::string word : {"plain-word_1.exr", "", "two words", "it's", "$HOME `ls` \"q\" \\ *?[a]",
                                   "Cloth={\"ex\": 2, \"pattern\": [1,2]}", "new\nline", "%04d"}) {
        const Result r = shell("printf '%s' " + shellQuote(word));
        EXPECT_EQ(r.output, word);
    }
    EXPECT_EQ(shellQuote("/abs/path.exr"), "/abs/path.exr");
    EXPECT_EQ(shellCommand({"a b", "c"}), "'a b' c");
}

TEST(FramePattern, FillsOneFieldAndKeepsLiteralPercents) {
    EXPECT_EQ(FramePattern::parse("shot_%04d.json")->name(7), "shot_0007.json");
    EXPECT_EQ(FramePattern::parse("a%db")->name(12345), "a12345b");
    EXPECT_EQ(FramePattern::parse("100%%_%3d.exr")->name(5), "100%_  5.exr");
    EXPECT_EQ(FramePattern::parse("f_%04d.exr")->withField("1-24"), "f_1-24.exr");
    EXPECT_FALSE(FramePattern::parse("plain.json"));
    EXPECT_FALSE(FramePattern::parse("100%%.json"));
    EXPECT_THROW(FramePattern::parse("%d_%d.json"), std::invalid_argument);
    EXPECT_THROW(FramePattern::parse("%s.json"), std::invalid_argument);
}

TEST(SubmitCommand, DryRunScriptsRunByHandGiveTheLocalFrameBitForBit) {
    TempDir dir;
    const fs::path root = dir.path() / "it's a folder";
    const std::string scene = writeScene(root / "my scene.json", 0.3f);
    const std::string out = (root / "out" / "frame $1.exr").string();
    // Flags too (--strict, --allow-any-path): each task gets them as flags, not as "--strict true".
    const std::vector<std::string> options = {"--width", "32", "--height", "24", "--integrator", "path", "--seed", "4",
                                              "--strict", "--allow-any-path", "--woven",
                                              "Cloth={\"ex\": 3, \"pattern\": [2, 1, 1], \"weft_color\": [0.8, 0.2, 0.1]}"};
    std::vector<std::string> submit = {"submit", scene, "--tasks", "3", "--spp", "5", "-o", out, "--dry-run",
                                       "--partition", "short", "--time", "5:00", "--cpus-per-task", "2",
                                       "--sbatch=--account=lab", "--requeue"};
    submit.insert(submit.end(), options.begin(), options.end());
    const Result dry = woven(submit);
    ASSERT_EQ(dry.status, 0) << dry.output;

    const fs::path job = root / "out" / "frame $1.slurm";
    EXPECT_THAT(dry.output, testing::HasSubstr("sbatch --parsable --job-name=woven-render --array=0-2 " +
                                               shellQuote("--output=" + job.string() + "/logs/render_%A_%a.log") +
                                               " --partition=short --time=5:00 --requeue --cpus-per-task=2 --account=lab " +
                                               shellQuote(job.string() + "/render.sbatch")));
    EXPECT_THAT(dry.output, testing::HasSubstr("--dependency=afterany:RENDER_JOB_ID"));
    ASSERT_TRUE(fs::exists(job / "render.sbatch"));
    EXPECT_FALSE(fs::exists(job / "logs" / "anything")) << "a dry run submits nothing";

    // Samples 0-4 over 3 tasks: 0, 1-2, 3-4.
    for (int task = 0; task < 3; ++task) {
        const Result r =
            shell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + shellQuote((job / "render.sbatch").string()));
        ASSERT_EQ(r.status, 0) << r.output;
    }
    for (const char* part : {"samples_0-0.exr", "samples_1-2.exr", "samples_3-4.exr"})
        EXPECT_TRUE(fs::exists(job / "parts" / part)) << part;
    const Result merge = shell("bash " + shellQuote((job / "merge.sbatch").string()));
    ASSERT_EQ(merge.status, 0) << merge.output;

    std::vector<std::string> local = {"render", scene, "--spp", "5", "-o", dir.file("local.exr")};
    local.insert(local.end(), options.begin(), options.end());
    ASSERT_EQ(woven(local).status, 0);
    expectSameFrame(out, dir.file("local.exr"));

    // A task that did not run: the merge names its samples and writes the partial frame only.
    fs::remove(out);
    fs::remove(job / "parts" / "samples_1-2.exr");
    const Result refused = shell("bash " + shellQuote((job / "merge.sbatch").string()));
    EXPECT_NE(refused.status, 0);
    EXPECT_THAT(refused.output, testing::HasSubstr("samples 1-2 missing"));
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(fs::exists(root / "out" / "frame $1.partial.exr"));
}

TEST(SubmitCommand, FramesFromAPatternOrAListOfScenes) {
    TempDir dir;
    writeScene(dir.path() / "shot_0001.json", 0.2f);
    writeScene(dir.path() / "shot_0002.json", 0.6f);
    const std::vector<std::string> common = {"--tasks", "2", "--spp", "2", "--width", "16", "--height", "12",
                                             "--integrator", "path", "--dry-run"};
    std::vector<std::string> pattern = {"submit", dir.file("shot_%04d.json"), "--frames", "1..2", "-o", dir.file("f_%04d.exr")};
    pattern.insert(pattern.end(), common.begin(), common.end());
    const Result r = woven(pattern);
    ASSERT_EQ(r.status, 0) << r.output;
    const fs::path job = dir.path() / "f_1-2.slurm";
    EXPECT_THAT(r.output, testing::HasSubstr("--array=0-3 "));
    for (int task = 0; task < 4; ++task)
        ASSERT_EQ(shell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + (job / "render.sbatch").string()).status, 0);
    for (int frame = 0; frame < 2; ++frame)
        ASSERT_EQ(shell("SLURM_ARRAY_TASK_ID=" + std::to_string(frame) + " bash " + (job / "merge.sbatch").string()).status, 0);
    EXPECT_TRUE(fs::exists(job / "parts" / "1" / "samples_1-1.exr"));
    const ExrImage one = readExr(dir.file("f_0001.exr")), two = readExr(dir.file("f_0002.exr"));
    EXPECT_LT(luminance(one.image.pixels.front()), luminance(two.image.pixels.front())) << "frame 2 has the brighter sky";

    // The same frames as a list of scene files, numbered by --frames.
    std::vector<std::string> list = {"submit", dir.file("shot_0001.json"), dir.file("shot_0002.json"), "--frames", "7..8",
                                     "-o", dir.file("g_%d.exr"), "--job-dir", dir.file("list job")};
    list.insert(list.end(), common.begin(), common.end());
    const Result listed = woven(list);
    ASSERT_EQ(listed.status, 0) << listed.output;
    EXPECT_THAT(listed.output, testing::HasSubstr(shellQuote(dir.file("g_8.exr"))));
    EXPECT_TRUE(fs::exists(dir.path() / "list job" / "parts" / "8"));
}

// With a noise threshold each task adapts within its own samples, to the threshold times
// sqrt(tasks), and the parts, whose pixels hold different numbers of samples, merge exactly.
TEST(SubmitCommand, EachTaskAdaptsToItsShareOfTheNoiseThreshold) {
    TempDir dir;
    const std::string scene = writeScene(dir.path() / "scene.json", 0.3f);
    const std::string out = dir.file("frame.exr");
    const Result dry = woven({"submit", scene, "--tasks", "4", "--spp", "80", "--noise-threshold", "0.1", "--width", "24",
                              "--height", "16", "--integrator", "path", "-o", out, "--dry-run"});
    ASSERT_EQ(dry.status, 0) << dry.output;
    EXPECT_THAT(dry.output, testing::HasSubstr("--noise-threshold 0.2 ")) << "0.1 x sqrt(4 tasks)";
    EXPECT_THAT(dry.output, testing::Not(testing::HasSubstr("--noise-threshold 0.1")));

    const fs::path job = dir.path() / "frame.slurm";
    for (int task = 0; task < 4; ++task) {
        const Result r =
            shell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + shellQuote((job / "render.sbatch").string()));
        ASSERT_EQ(r.status, 0) << r.output;
    }
    const Result merge = shell("bash " + shellQuote((job / "merge.sbatch").string()));
    ASSERT_EQ(merge.status, 0) << merge.output;
    const ExrImage frame = readExr(out);
    std::vector<float> sum(frame.sampleCount.size(), 0.0f);
    for (const fs::directory_entry& part : fs::directory_iterator(job / "parts")) {
        const ExrImage p = readExr(part.path().string());
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += p.sampleCount[i];
    }
    EXPECT_EQ(frame.sampleCount, sum);
    // The sky stops after the 16 samples every pixel takes in each task; the cloth takes more.
    EXPECT_EQ(*std::min_element(sum.begin(), sum.end()), 4 * 16.0f);
    EXPECT_GT(*std::max_element(sum.begin(), sum.end()), 4 * 16.0f);
}

TEST(SubmitCommand, BadRequestsFailBeforeAnythingIsSubmitted) {
    TempDir dir;
    const std::string scene = writeScene(dir.path() / "scene.json", 0.3f);
    const std::string out = dir.file("frame.exr");
    const auto fails = [&](const std::vector<std::string>& args, const std::string& message) {
        const Result r = woven(args);
        EXPECT_NE(r.status, 0) << message;
        EXPECT_THAT(r.output, testing::HasSubstr(message));
    };
    fails({"submit", scene, "--tasks", "9", "--spp", "8", "-o", out}, "--tasks 9 is more than the 8 samples per pixel");
    fails({"submit", scene, "--tasks", "2", "-o", dir.file("frame.png")}, "frame.png: woven submit writes EXR");
    fails({"submit", scene, scene, "--tasks", "2", "-o", out}, "with several frames, OUT needs a frame number field");
    fails({"submit", scene, "--frames", "1..3", "--tasks", "2", "-o", dir.file("f_%d.exr")}, "has no frame number field");
    fails({"submit", scene, "--frames", "3..1", "--tasks", "2", "-o", dir.file("f_%d.exr")}, "the first frame is after the last");
    fails({"submit", scene, "--frames", "0..1000000000000", "--tasks", "2", "-o", dir.file("f_%d.exr")},
          "--frames 0..1000000000000: frame numbers are at most 999999999");
    fails({"submit", dir.file("missing.json"), "--tasks", "2", "-o", out}, "missing.json: no such scene file");
    fails({"submit", scene, "--tasks", "2", "--woven", "Nope={}", "-o", out}, "'Nope' names nothing");
    fails({"submit", scene, "--tasks", "2", "--first-sample", "3", "-o", out}, "--first-sample");
    // Without sbatch on PATH, nothing to submit with: a clear error.
    const Result noSlurm = shell("PATH=/nonexistent " + shellCommand({WOVEN_EXECUTABLE, "submit", scene, "--tasks", "2", "-o", out}));
    EXPECT_NE(noSlurm.status, 0);
    EXPECT_THAT(noSlurm.output, testing::HasSubstr("sbatch: cannot run it"));
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace woven
