// The command line's mistakes answered in woven's words: a mistyped command or option is named
// with the one meant, a bad choice lists the choices, and no parser internals are shown.
#include <gtest/gtest.h>

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

TEST(CommandLineMessages, ClosestNameTakesOnlyTyposOfTheWord) {
    const std::vector<std::string> names = {"render", "preview", "merge", "pattern"};
    EXPECT_EQ(closestName("rendr", names), "render");
    EXPECT_EQ(closestName("mrege", names), "merge");  // a swap is two edits: still a typo of 5 letters
    EXPECT_EQ(closestName("xyz", names), "");
    EXPECT_EQ(closestName("", names), "");
}

}  // namespace
}  // namespace woven
