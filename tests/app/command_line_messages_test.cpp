// The command line's mistakes answered in woven's words: a mistyped command or option is named
// with the one meant, a bad choice lists the choices, and no parser internals are shown.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <tuple>
#include <vector>

#include "parse_errors.h"
#include "woven_command.h"

namespace woven {
namespace {

using test::runWovenCommand;

const std::string kScene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";

TEST(CommandLineMessages, MistypedCommandSuggestsTheCommand) {
    const auto r = runWovenCommand("rendr x.glb");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("'rendr' is not a woven command; did you mean 'render'?"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("A subcommand is required"), std::string::npos) << r.output;
    // Nothing close: the commands are listed instead of a guess.
    const auto far = runWovenCommand("frobnicate");
    EXPECT_NE(far.status, 0);
    EXPECT_NE(far.output.find("the commands are"), std::string::npos) << far.output;
    EXPECT_NE(far.output.find("render"), std::string::npos) << far.output;
    EXPECT_EQ(far.output.find("did you mean"), std::string::npos) << far.output;
}

TEST(CommandLineMessages, MistypedOptionSuggestsTheOption) {
    const auto r = runWovenCommand("render " + kScene + " --sppp 3 -o /nonexistent/x.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("woven render: error: unknown option '--sppp'; did you mean '--spp'?"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("not expected"), std::string::npos) << r.output;
}

TEST(CommandLineMessages, BadToneMapListsTheCurvesWithoutParserInternals) {
    const auto r = runWovenCommand("render " + kScene + " --tone-map filmic -o /nonexistent/x.png");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("--tone-map: 'filmic' is not a tone curve woven has: aces, clamp or reinhard"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("FAILED"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("->"), std::string::npos) << r.output;
}

TEST(CommandLineMessages, RenderHelpHasNoPreviewOnlyOption) {
    const auto render = runWovenCommand("render --help");
    EXPECT_EQ(render.status, 0);
    EXPECT_EQ(render.output.find("--no-filter"), std::string::npos) << render.output;
    const auto preview = runWovenCommand("preview --help");
    EXPECT_NE(preview.output.find("--no-filter"), std::string::npos) << preview.output;
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
             {"--noise-threshold", "-0.5", "--noise-threshold: '-0.5' is outside the range: it must be at least 0"}}) {
        const auto r = runWovenCommand("render " + kScene + " " + option + " " + value + " -o " + file("out.png"));
        EXPECT_NE(r.status, 0) << option << " " << value;
        EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("179769"), std::string::npos) << "the largest double in full: " << r.output;
        EXPECT_FALSE(std::filesystem::exists(file("out.png")));
    }
}

// nlohmann's tags ("[json.exception.out_of_range.406]") are the library's words, not woven's.
TEST_F(NumberOptions, JsonProblemsAreSaidWithoutTheParsersTags) {
    std::ofstream(file("huge.json")) << R"({"gltf": "cloth_drape.glb", "render": {"width": 1e400}})";
    const auto scene = runWovenCommand("render " + file("huge.json") + " -o " + file("out.png"));
    EXPECT_NE(scene.status, 0);
    EXPECT_NE(scene.output.find("huge.json: not valid JSON: the number 1e400 is beyond the range of a double"),
              std::string::npos) << scene.output;
    EXPECT_EQ(scene.output.find("json.exception"), std::string::npos) << scene.output;
    const auto woven = runWovenCommand("render " + kScene + " --woven 'Cloth={\"ex\": 1e400' -o " + file("out.png"));
    EXPECT_NE(woven.status, 0);
    EXPECT_NE(woven.output.find("--woven Cloth: not valid JSON"), std::string::npos) << woven.output;
    EXPECT_EQ(woven.output.find("json.exception"), std::string::npos) << woven.output;
    std::ofstream(file("broken.gltf")) << R"({"asset": {"version": "2.0"},)";
    const auto gltf = runWovenCommand("render " + file("broken.gltf") + " -o " + file("out.png"));
    EXPECT_NE(gltf.status, 0);
    EXPECT_NE(gltf.output.find("broken.gltf: cannot read glTF"), std::string::npos) << gltf.output;
    EXPECT_EQ(gltf.output.find("json.exception"), std::string::npos) << gltf.output;
    std::ofstream(file("query.jsonl")) << R"({"material": {"ex": 1e400}})" << "\n";
    const auto eval = runWovenCommand("bsdf-eval < " + file("query.jsonl"));
    EXPECT_NE(eval.output.find("not valid JSON: the number 1e400"), std::string::npos) << eval.output;
    EXPECT_EQ(eval.output.find("json.exception"), std::string::npos) << eval.output;
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
