// `woven pattern --wif` and `--png` as a user runs them (a child process through popen).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>

#include "image_io.h"
#include "temp_dir.h"
#include "wif_test_files.h"

#include "../common/run_woven.h"

namespace woven {
namespace {

using test::RunResult;
using test::runWoven;

std::string joined(const std::vector<std::string>& rows) {
    std::string s;
    for (const auto& r : rows) s += r + "\n";
    return s;
}

class PatternCommand : public ::testing::Test {
protected:
    std::string write(const std::string& name, const std::string& text) {
        const std::string path = dir_.file(name);
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    test::TempDir dir_;
};

TEST_F(PatternCommand, PrintsTheDraftsTopYarnMap) {
    const std::string twill = write("twill.wif", test::twillWif());
    RunResult r = runWoven("pattern --wif '" + twill + "'");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, joined(test::twillMap()));  // one repeat by default
    r = runWoven("pattern --wif '" + write("plain.wif", test::plainLiftplanWif()) + "' --size 6,3");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "|-|-|-\n-|-|-|\n|-|-|-\n");  // repeated past the draft's 4 x 4
}

TEST_F(PatternCommand, WarningsGoToStderrAndTheMapStillPrints) {
    const std::string path = write("odd.wif", "stray text\n" + test::twillWif());
    const RunResult out = runWoven("pattern --wif '" + path + "' 2>/dev/null");
    EXPECT_EQ(out.exitCode, 0);
    EXPECT_EQ(out.out, joined(test::twillMap()));
    const RunResult err = runWoven("pattern --wif '" + path + "' 2>&1 >/dev/null");
    EXPECT_EQ(err.out, "warning: " + path + ": 1 line of text before the first section ignored\n");
}

TEST_F(PatternCommand, BadDraftsFailNamingTheFile) {
    const std::string noTreadling = write("no_treadling.wif", test::replaced(test::twillWif(), "[TREADLING]", "[X]"));
    RunResult r = runWoven("pattern --wif '" + noTreadling + "' 2>&1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("error: " + noTreadling + ": the draft has no interlacement"), std::string::npos) << r.out;
    r = runWoven("pattern --wif '" + dir_.file("missing.wif") + "' 2>&1");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("missing.wif: no such file"), std::string::npos) << r.out;
    EXPECT_NE(runWoven("pattern --pattern 1,1,1 --wif '" + noTreadling + "' 2>/dev/null").exitCode, 0);
}

TEST_F(PatternCommand, PngDrawsTheDrawdownInThreadColours) {
    // Red warp, blue weft, 2/2 twill; 3 pixels per cell.
    std::string text = test::replaced(test::twillWif(), "1=255,255,255\n2=0,0,0", "1=255,0,0\n2=0,0,255");
    const std::string png = dir_.file("twill.png");
    const RunResult r = runWoven("pattern --wif '" + write("twill.wif", text) + "' --png '" + png + "' --cell-pixels 3");
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "");  // the PNG replaces the printed map
    const Image image = readImage(png, ChannelEncoding::Linear);
    ASSERT_EQ(image.width, 24);
    ASSERT_EQ(image.height, 24);
    const std::vector<std::string> map = test::twillMap();
    for (int V = 0; V < 8; ++V)
        for (int U = 0; U < 8; ++U)
            EXPECT_EQ(image.at(3 * U + 1, 3 * V + 2), map[size_t(V)][size_t(U)] == '|' ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1))
                << U << "," << V;
}

TEST_F(PatternCommand, PngOfAPatternIsBlackWarpOnWhiteWeft) {
    const std::string png = dir_.file("twill.png");
    ASSERT_EQ(runWoven("pattern --pattern 1,2,1 --size 6,3 --png '" + png + "' --cell-pixels 1").exitCode, 0);
    const Image image = readImage(png, ChannelEncoding::Linear);
    ASSERT_EQ(image.width, 6);
    ASSERT_EQ(image.height, 3);
    const char* rows[] = {"-||-||", "||-||-", "|-||-|"};  // MODEL.md's twill (1,2,1)
    for (int V = 0; V < 3; ++V)
        for (int U = 0; U < 6; ++U) EXPECT_EQ(image.at(U, V), glm::vec3(rows[V][U] == '|' ? 0.0f : 1.0f));
}

TEST_F(PatternCommand, BadDraftWritesNoPng) {
    const std::string png = dir_.file("bad.png");
    const std::string bad = write("bad.wif", "[WIF]\nVersion=1.1\n[WEAVING]\nShafts=4\n");
    EXPECT_NE(runWoven("pattern --wif '" + bad + "' --png '" + png + "' 2>/dev/null").exitCode, 0);
    EXPECT_FALSE(std::ifstream(png).good());
}

}  // namespace
}  // namespace woven
