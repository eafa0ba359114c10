// `woven share` in a real browser: Debian's Chromium, headless, driven by puppeteer-core (npm),
// opens the page from disk with the network off (share_page_check.js), and the test checks that
// <model-viewer> loaded the cloth with no console error, that the cloth fills the frame, and that
// its mean colour is near the poster's (woven's final render of the same view), not the white
// page's. Skipped, saying what is missing, without node, puppeteer-core or chromium
// (tools/install-deps.sh --tests installs them).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../common/run_woven.h"

namespace woven {
namespace {

using nlohmann::json;

std::string missingTools() {
    std::string missing;
    if (::access(NODE_EXECUTABLE, X_OK) != 0) missing += " node";
    if (!std::filesystem::exists(std::string(NODE_MODULES) + "/puppeteer-core")) missing += " puppeteer-core (npm, in " NODE_MODULES ")";
    if (::access(CHROMIUM, X_OK) != 0) missing += " chromium";
    return missing;
}

class SharePageTest : public test::CommandTest {};

TEST_F(SharePageTest, ThePageShowsTheClothInChromiumOfflineWithoutErrors) {
    if (const std::string missing = missingTools(); !missing.empty()) GTEST_SKIP() << "not installed:" << missing;
    const std::string page = file("page");
    const test::RunResult made = test::runWovenCommand("share '" + std::string(WOVEN_ASSETS_DIR) + "/default_scene.json' -o '" + page +
                                                       "' --size 64 --poster-size 160 --poster-spp 8");
    ASSERT_EQ(made.exitCode, 0) << made.out;
    for (const char* f : {"index.html", "scene.glb", "poster.png", "environment.hdr", "model-viewer.min.js"})
        EXPECT_TRUE(std::filesystem::exists(page + "/" + f)) << f;
    const std::string command = "NODE_PATH='" NODE_MODULES "' timeout 180 '" NODE_EXECUTABLE "' '" SHARE_PAGE_CHECK "' '" + page +
                                "/index.html' '" CHROMIUM "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_TRUE(pipe);
    std::string out;
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    pclose(pipe);
    const size_t line = out.rfind("{\"loaded\"");
    ASSERT_NE(line, std::string::npos) << out;
    const json r = json::parse(out.substr(line));
    EXPECT_TRUE(r["loaded"].get<bool>()) << out;
    EXPECT_TRUE(r["errors"].empty()) << r["errors"].dump();
    // The default scene's camera sees cloth only: model-viewer's frame is covered.
    EXPECT_GT(r["frame"]["coverage"].get<double>(), 0.9);
    // Measured: the frame's mean sRGB (82, 86, 103) against the poster's (92, 98, 124), 26
    // apart; the page's white is 270 from the poster.
    double toPoster = 0.0, whiteToPoster = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double frame = r["frame"]["mean"][c], poster = r["poster"]["mean"][c];
        toPoster += (frame - poster) * (frame - poster), whiteToPoster += (255.0 - poster) * (255.0 - poster);
    }
    EXPECT_LT(std::sqrt(toPoster), 0.25 * std::sqrt(whiteToPoster)) << out;
}

TEST_F(SharePageTest, WithoutModelViewerItSaysWhereToGetIt) {
    const std::string env = "WOVEN_MODEL_VIEWER='" + file("nothing.js") + "' ";
    const std::string command = env + "'" + WOVEN_EXECUTABLE + "' share '" + WOVEN_ASSETS_DIR + "/default_scene.json' -o '" + file("page3") + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buffer[4096];
    for (size_t n; pipe && (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    const int status = pipe ? pclose(pipe) : -1;
    EXPECT_NE(status, 0);
    EXPECT_NE(out.find("model-viewer"), std::string::npos) << out;
    EXPECT_NE(out.find("tools/install-deps.sh --share"), std::string::npos) << out;
    EXPECT_FALSE(std::filesystem::exists(file("page3")));
}

TEST_F(SharePageTest, ASceneWithNothingWovenIsRefusedAndLeavesNoFolder) {
    const test::RunResult r = test::runWovenCommand("share '" + std::string(WOVEN_ASSETS_DIR) + "/lampshade.gltf' -o '" + file("page") + "'");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("no part of the scene is woven"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(file("page")));
}

}  // namespace
}  // namespace woven
