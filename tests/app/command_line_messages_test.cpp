// The command line's mistakes answered in woven's words: a mistyped command or option is named
// with the one meant, a bad choice lists the choices, and no parser internals are shown.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <tuple>
#include <vector>

#include "parse_errors.h"
#include "progress_bar.h"
#include "../common/run_woven.h"

namespace woven {
namespace {

using test::runWovenCommand;

const std::string kScene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";

TEST(CommandLineMessages, MistypedCommandSuggestsTheCommand) {
    const auto r = runWovenCommand("rendr x.glb");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("'rendr' is not a woven command; did you mean 'render'?"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("A subcommand is required"), std::string::npos) << r.out;
    // Nothing close: the commands are listed instead of a guess.
    const auto far = runWovenCommand("frobnicate");
    EXPECT_NE(far.exitCode, 0);
    EXPECT_NE(far.out.find("the commands are"), std::string::npos) << far.out;
    EXPECT_NE(far.out.find("render"), std::string::npos) << far.out;
    EXPECT_EQ(far.out.find("did you mean"), std::string::npos) << far.out;
}

TEST(CommandLineMessages, MistypedOptionSuggestsTheOption) {
    const auto r = runWovenCommand("render " + kScene + " --sppp 3 -o /nonexistent/x.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("woven render: error: unknown option '--sppp'; did you mean '--spp'?"), std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("not expected"), std::string::npos) << r.out;
}

TEST(CommandLineMessages, BadToneMapListsTheCurvesWithoutParserInternals) {
    const auto r = runWovenCommand("render " + kScene + " --tone-map filmic -o /nonexistent/x.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("--tone-map: 'filmic' is not a tone curve woven has: aces, clamp or reinhard"), std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("->"), std::string::npos) << r.out;
}

TEST(CommandLineMessages, RenderHelpHasNoPreviewOnlyOption) {
    const auto render = runWovenCommand("render --help");
    EXPECT_EQ(render.exitCode, 0);
    EXPECT_EQ(render.out.find("--no-filter"), std::string::npos) << render.out;
    const auto preview = runWovenCommand("preview --help");
    EXPECT_NE(preview.out.find("--no-filter"), std::string::npos) << preview.out;
}

// CLI11's checks let NaN through (every comparison with it is false): --exposure nan gave a black
// frame with exit 0, --time nan was ignored. Each is refused naming the option, nothing written.
class NumberOptions : public test::CommandTest {};

TEST_F(NumberOptions, NonFiniteAndOutOfRangeNumbersAreRefusedNamingTheOption) {
    for (const auto& [option, value, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"--exposure", "nan", "--exposure: 'nan' is not a finite number"},
             {"--exposure", "inf", "--exposure: 'inf' is not a finite number"},
             {"--exposure", "41", "--exposure: '41' is outside the range: it must be from -40 to 40"},
             {"--time", "nan", "--time: 'nan' is not a finite number"},
             {"--time", "-1", "--time: '-1' must be above 0"},
             {"--noise-threshold", "nan", "--noise-threshold: 'nan' is not a finite number"},
             {"--noise-threshold", "-0.5", "--noise-threshold: '-0.5' is outside the range: it must be at least 0"},
             // Options that count take whole numbers, and say so.
             {"--width", "2.5", "--width: '2.5' is not a whole number (it must be one from 1 to 32768)"},
             {"--spp", "1e3", "--spp: '1e3' is not a whole number"},
             {"--width", "40000", "--width: '40000' is outside the range: it must be from 1 to 32768"},
             {"--threads", "-1", "--threads: '-1' is outside the range: it must be at least 0"}}) {
        const auto r = runWovenCommand("render " + kScene + " " + option + " " + value + " -o " + file("out.png"));
        EXPECT_NE(r.exitCode, 0) << option << " " << value;
        EXPECT_NE(r.out.find(says), std::string::npos) << r.out;
        EXPECT_EQ(r.out.find("179769"), std::string::npos) << "the largest double in full: " << r.out;
        EXPECT_FALSE(std::filesystem::exists(file("out.png")));
    }
}

// Numbers read as written: CLI11 read a leading 0 as octal (`--spp 010` rendered 8 samples,
// `pattern --pattern 010,1,0` drew 8 weft elements) and "-1" into the unsigned seed as 2^64 - 1. A bad choice and a wrong count of values are said in
// woven's words, not CLI11's ("foo not in {path,bdpt,auto}", "At Most 1 required but received 2").
TEST_F(NumberOptions, NumbersAreReadAsWrittenAndMistakesAreSaidInWovensWords) {
    const auto r = runWovenCommand("render " + kScene + " --width 010 --height 8 --spp 010 -o " + file("out.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find(", 10 spp"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(", 10x8,"), std::string::npos) << r.out;
    const auto pattern = runWovenCommand("pattern --pattern 010,1,0");
    EXPECT_EQ(pattern.exitCode, 0) << pattern.out;
    EXPECT_EQ(pattern.out.substr(0, pattern.out.find('\n')), std::string(10, '-') + "|") << pattern.out;
    const std::string out = " -o " + file("refused.exr");
    for (const auto& [options, says] : std::vector<std::pair<std::string, std::string>>{
             {"render " + kScene + " --seed -1" + out, "--seed: '-1' is outside the range: it must be at least 0"},
             {"render " + kScene + " --integrator foo" + out, "--integrator: 'foo' is not one of path, bdpt or auto"},
             {"render " + kScene + " --sampler {}" + out, "--sampler: '{}' is not one of independent or sobol"},
             {"render " + kScene + " --width 10 --width 20" + out, "--width: takes one value, given 2 (give the option once)"},
             {"converge " + kScene + " --filter maybe --out-dir " + file("refused"), "--filter: 'maybe' is not one of on or off"},
             {"pattern --size 4", "--size: takes 2 values, given 1"},
             // An empty value stood for "not given": -o '' wrote the default name, --environment ''
             // kept the scene's light.
             {"render " + kScene + " --environment ''" + out, "--environment: '' names nothing"},
             {"render " + kScene + " -o ''", "--out: '' names nothing"},
             // --list renders nothing: the options of a render were ignored without a word.
             {"render " + kScene + " --list" + out, "--out and --list cannot be given together"},
             {"render " + kScene + " --spp 4 --list", "--spp and --list cannot be given together"},
             // An azimuth of NaN drew a plot of zeros.
             {"bsdf-plot --phi nan" + out, "--phi: 'nan' is not a finite number"}}) {
        const auto refused = runWovenCommand(options);
        EXPECT_NE(refused.exitCode, 0) << options;
        EXPECT_NE(refused.out.find(says), std::string::npos) << refused.out;
        EXPECT_EQ(refused.out.find("required but received"), std::string::npos) << refused.out;
        EXPECT_EQ(refused.out.find("not in {"), std::string::npos) << refused.out;
    }
    EXPECT_FALSE(std::filesystem::exists(file("refused.exr")));
    EXPECT_FALSE(std::filesystem::exists(file("refused")));
}

// More threads than the machine offers is valid (a job script written for a larger machine): the
// render runs, capped to the cores, and says so once.
TEST_F(NumberOptions, MoreThreadsThanCoresRenderWithOneWarning) {
    const auto r = runWovenCommand("render " + kScene + " --width 8 --height 8 --spp 1 --threads 100000 -o " + file("out.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    const std::string warning = "warning: --threads 100000: woven may use ";
    ASSERT_NE(r.out.find(warning), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(warning, r.out.find(warning) + 1), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(file("out.exr")));
}

// nlohmann's tags ("[json.exception.out_of_range.406]") are the library's words, not woven's.
TEST_F(NumberOptions, JsonProblemsAreSaidWithoutTheParsersTags) {
    std::ofstream(file("huge.json")) << R"({"gltf": "cloth_drape.glb", "render": {"width": 1e400}})";
    const auto scene = runWovenCommand("render " + file("huge.json") + " -o " + file("out.png"));
    EXPECT_NE(scene.exitCode, 0);
    EXPECT_NE(scene.out.find("huge.json: not valid JSON: the number 1e400 is beyond the range of a double"),
              std::string::npos) << scene.out;
    EXPECT_EQ(scene.out.find("json.exception"), std::string::npos) << scene.out;
    const auto woven = runWovenCommand("render " + kScene + " --woven 'Cloth={\"ex\": 1e400' -o " + file("out.png"));
    EXPECT_NE(woven.exitCode, 0);
    EXPECT_NE(woven.out.find("--woven Cloth: not valid JSON"), std::string::npos) << woven.out;
    EXPECT_EQ(woven.out.find("json.exception"), std::string::npos) << woven.out;
    std::ofstream(file("broken.gltf")) << R"({"asset": {"version": "2.0"},)";
    const auto gltf = runWovenCommand("render " + file("broken.gltf") + " -o " + file("out.png"));
    EXPECT_NE(gltf.exitCode, 0);
    EXPECT_NE(gltf.out.find("broken.gltf: cannot read glTF"), std::string::npos) << gltf.out;
    EXPECT_EQ(gltf.out.find("json.exception"), std::string::npos) << gltf.out;
    std::ofstream(file("query.jsonl")) << R"({"material": {"ex": 1e400}})" << "\n";
    const auto eval = runWovenCommand("bsdf-eval < " + file("query.jsonl"));
    EXPECT_NE(eval.out.find("not valid JSON: the number 1e400"), std::string::npos) << eval.out;
    EXPECT_EQ(eval.out.find("json.exception"), std::string::npos) << eval.out;
}

// A preview wider than the OpenGL implementation draws was "float framebuffer is incomplete":
// the limit is said by option, or (where the implementation draws it) the frame is written.
TEST_F(NumberOptions, APreviewBeyondTheOpenGlLimitSaysTheLimit) {
    const auto r = runWovenCommand("preview --headless --width 32768 --height 1 --screenshot " + file("wide.png"));
    if (r.exitCode == 0) return;
    EXPECT_NE(r.out.find("this OpenGL implementation draws at most"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("incomplete"), std::string::npos) << r.out;
}

// --time 1e300 printed a negative duration (the seconds overflowed a long).
TEST(CommandLineMessages, DurationsBeyondYearsAreSaidInSeconds) {
    EXPECT_EQ(formatDuration(75.0), "1:15");
    EXPECT_EQ(formatDuration(3725.0), "1:02:05");
    EXPECT_EQ(formatDuration(1e300), "1e+300 s");
    EXPECT_EQ(formatDuration(-1.0), "?");
}

TEST(CommandLineMessages, ClosestNameTakesOnlyTyposOfTheWord) {
    const std::vector<std::string> names = {"render", "preview", "merge", "pattern"};
    EXPECT_EQ(closestName("rendr", names), "render");
    EXPECT_EQ(closestName("mrege", names), "merge");  // a swap is two edits: still a typo of 5 letters
    EXPECT_EQ(closestName("xyz", names), "");
    EXPECT_EQ(closestName("", names), "");
}

}  // namespace
}  // namespace woven
