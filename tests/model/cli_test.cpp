// The `woven` CLI as a user runs it (a child process through popen): `pattern` against
// MODEL.md's drawings, `bsdf-eval` against the independent double-precision reference BRDF,
// its error lines, and `bsdf-plot`'s PNG.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "reference_brdf.h"

#include "../common/run_woven.h"

namespace woven {
namespace {

using test::RunResult;
using test::runWoven;

std::string tempPath(const std::string& name) {
    return ::testing::TempDir() + "woven_test_cli_" + std::to_string(::getpid()) + "_" + name;
}

// Runs `woven bsdf-eval` with `lines` on stdin; returns the parsed output lines.
std::vector<nlohmann::json> bsdfEval(const std::vector<nlohmann::json>& lines, int& exitCode) {
    const std::string input = tempPath("eval.jsonl");
    {
        std::ofstream f(input);
        for (const auto& l : lines) f << (l.is_string() ? l.get<std::string>() : l.dump()) << "\n";
    }
    const RunResult r = runWoven("bsdf-eval < '" + input + "' 2>/dev/null");
    std::remove(input.c_str());
    exitCode = r.exitCode;
    std::vector<nlohmann::json> out;
    std::istringstream s(r.out);
    std::string line;
    while (std::getline(s, line)) out.push_back(nlohmann::json::parse(line));
    return out;
}

TEST(Cli, PatternMatchesModelDrawings) {
    const RunResult plain = runWoven("pattern --pattern 1,1,1 --size 8,3");
    EXPECT_EQ(plain.exitCode, 0);
    EXPECT_EQ(plain.out, "-|-|-|-|\n|-|-|-|-\n-|-|-|-|\n");
    const RunResult twill = runWoven("pattern --pattern 1,2,1 --size 12,3");
    EXPECT_EQ(twill.exitCode, 0);
    EXPECT_EQ(twill.out, "-||-||-||-||\n||-||-||-||-\n|-||-||-||-|\n");
    const RunResult satin = runWoven("pattern --pattern 9,1,3 --size 20,3");
    EXPECT_EQ(satin.exitCode, 0);
    EXPECT_EQ(satin.out, "---------|---------|\n------|---------|---\n---|---------|------\n");
}

TEST(Cli, PatternRejectsBadInput) {
    EXPECT_NE(runWoven("pattern --pattern 0,0,1 2>/dev/null").exitCode, 0);
    EXPECT_NE(runWoven("pattern --pattern 1,1,1 --size 0,3 2>/dev/null").exitCode, 0);
}

// Flat yarns (cy 0), full width, no noise or crimp: the woven BSDF must be the plain
// Ashikhmin-Shirley lobe with x along u on weft and along v on warp. Weft and warp get
// different exponents and colours so a swapped axis or parameter set shows.
TEST(Cli, BsdfEvalMatchesReferenceOnWeftAndWarp) {
    const nlohmann::json material = {
        {"pattern", {1, 1, 1}}, {"cy", 0.0}, {"yarn_width", 1.0}, {"noise", 0.0}, {"crimp", 0.0},
        {"ex", 200.0}, {"ey", 5.0}, {"warp_ex", 30.0}, {"warp_ey", 400.0}, {"rs", 0.06},
        {"weft_color", {0.5, 0.2, 0.1}}, {"warp_color", {0.1, 0.3, 0.6}}};
    const test::ReferenceAS weft{200.0, 5.0, 0.06, {0.5, 0.2, 0.1}};
    const test::ReferenceAS warp{30.0, 400.0, 0.06, {0.1, 0.3, 0.6}};
    // Plain weave, one element per UV unit: (U + V) even -> weft, odd -> warp.
    struct Point { glm::dvec2 uv; bool warp; };
    const Point points[] = {{{0.3, 0.6}, false}, {{1.4, 0.5}, true}, {{-0.7, 0.4}, true}, {{-3.2, -5.9}, false}};
    struct Dirs { double thetaO, phiO, thetaI, phiI; };
    const Dirs dirs[] = {{0.4, 0.0, 0.4, 3.14159}, {1.0, 0.3, 0.9, 3.6}, {0.7, 1.57, 0.6, 4.6},
                         {1.3, 2.0, 0.2, 5.5}, {0.1, 0.0, 1.2, 1.0}, {0.8, 0.5, 0.8, 3.7}};
    std::vector<nlohmann::json> lines;
    std::vector<glm::dvec3> expected;
    std::vector<std::string> expectedYarn;
    for (const Point& p : points)
        for (const Dirs& d : dirs) {
            const glm::vec3 wo = test::sphericalDirection(d.thetaO, d.phiO);
            const glm::vec3 wi = test::sphericalDirection(d.thetaI, d.phiI);
            lines.push_back({{"material", material}, {"uv", {p.uv.x, p.uv.y}},
                             {"wo", {wo.x, wo.y, wo.z}}, {"wi", {wi.x, wi.y, wi.z}}});
            // Lobe frame: weft x = +u (world x); warp x = +v (world y), y = z cross x = -u.
            auto local = [&](const glm::vec3& w) {
                return p.warp ? glm::dvec3(w.y, -w.x, w.z) : glm::dvec3(w);
            };
            expected.push_back((p.warp ? warp : weft).eval(local(wo), local(wi)));
            expectedYarn.push_back(p.warp ? "warp" : "weft");
        }
    int exitCode = -1;
    const auto out = bsdfEval(lines, exitCode);
    EXPECT_EQ(exitCode, 0);
    ASSERT_EQ(out.size(), lines.size());
    for (size_t i = 0; i < out.size(); ++i) {
        SCOPED_TRACE(lines[i].dump());
        ASSERT_TRUE(out[i].contains("f")) << out[i].dump();
        EXPECT_EQ(out[i]["yarn"], expectedYarn[i]);
        EXPECT_GT(out[i]["pdf"].get<double>(), 0.0);
        for (int c = 0; c < 3; ++c) {
            // Float evaluation against double: exponents up to 400 amplify the ~1e-7 error of
            // n.h by N, so allow 1e-3 relative; a swapped axis or colour is off by far more.
            const double want = expected[i][c];
            EXPECT_NEAR(out[i]["f"][c].get<double>(), want, 1e-3 * want + 1e-7);
        }
    }
}

// Narrow yarns and no backing: the corner of an element is covered by neither yarn.
TEST(Cli, BsdfEvalReportsTrueGap) {
    const nlohmann::json material = {{"pattern", {1, 1, 1}}, {"yarn_width", 0.5}, {"warp_width", 0.5},
                                     {"backing", 0}};
    const std::vector<nlohmann::json> lines = {
        {{"material", material}, {"uv", {0.05, 0.05}}, {"wo", {0, 0, 1}}, {"wi", {0.3, 0, 1}}},
        {{"material", material}, {"uv", {2.95, -0.05}}, {"wo", {0, 0, 1}}, {"wi", {0.3, 0, 1}}},
        // Element centre: on the weft yarn of element (0, 0).
        {{"material", material}, {"uv", {0.5, 0.5}}, {"wo", {0, 0, 1}}, {"wi", {0.3, 0, 1}}}};
    int exitCode = -1;
    const auto out = bsdfEval(lines, exitCode);
    EXPECT_EQ(exitCode, 0);
    ASSERT_EQ(out.size(), 3u);
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(out[k]["yarn"], "gap") << out[k].dump();
        EXPECT_EQ(out[k]["f"], nlohmann::json({0.0, 0.0, 0.0}));
        EXPECT_EQ(out[k]["pdf"].get<double>(), 0.0);
    }
    EXPECT_EQ(out[2]["yarn"], "weft");
    EXPECT_GT(out[2]["f"][0].get<double>(), 0.0);
}

// Every bad line gets an {"error": ...} line naming the problem, good lines still get answers,
// and the exit status reports the failure.
// Issue 21: f was 0 at uv 1e20 for every direction. Uv 1e7 + 0.3037 (a double resolves it) is
// the point 0.3037 shows, to rounding in uv x repeat (1e-3 relative); 1e20 and -1e300 (a double's
// values 1.6e4 and more apart) are the far field, one answer for both.
TEST(Cli, BsdfEvalAnswersHugeUvsWithTheWrappedPointOrTheFarField) {
    const nlohmann::json material = {{"pattern", {1, 3, 1}}, {"repeat", {100, 100}}, {"yarn_width", 0.8}};
    auto line = [&](double uv) {
        return nlohmann::json{{"material", material}, {"uv", {uv, uv}}, {"wo", {-0.2, 0.1, 0.95}}, {"wi", {0.3, 0.2, 0.9}}};
    };
    int exitCode = -1;
    const auto out = bsdfEval({line(0.3037), line(1e7 + 0.3037), line(1e20), line(-1e300)}, exitCode);
    EXPECT_EQ(exitCode, 0);
    ASSERT_EQ(out.size(), 4u);
    EXPECT_EQ(out[1]["yarn"], out[0]["yarn"]);
    for (int c = 0; c < 3; ++c) {
        const double f0 = out[0]["f"][c].get<double>();
        ASSERT_GT(f0, 0.0);
        EXPECT_NEAR(out[1]["f"][c].get<double>(), f0, 1e-3 * f0);
        EXPECT_GT(out[2]["f"][c].get<double>(), 0.0);
        EXPECT_EQ(out[3]["f"][c], out[2]["f"][c]);
    }
    EXPECT_EQ(out[2]["yarn"], "far");
    EXPECT_GT(out[2]["pdf"].get<double>(), 0.0);
}

TEST(Cli, BsdfEvalErrorLines) {
    const nlohmann::json good = {{"material", {{"cy", 0.2}}}, {"uv", {0.5, 0.5}}, {"wo", {0, 0, 1}}, {"wi", {0, 0.2, 1}}};
    nlohmann::json outOfRange = good;
    outOfRange["material"]["cy"] = 1.5;
    nlohmann::json unknownKey = good;
    unknownKey["material"]["shininess"] = 3;
    nlohmann::json zeroDir = good;
    zeroDir["wi"] = {0, 0, 0};
    const std::vector<nlohmann::json> lines = {good, "{\"material\": {", outOfRange, unknownKey, zeroDir, good};
    int exitCode = 0;
    const auto out = bsdfEval(lines, exitCode);
    EXPECT_NE(exitCode, 0);
    ASSERT_EQ(out.size(), lines.size());
    EXPECT_TRUE(out[0].contains("f"));
    EXPECT_TRUE(out[5].contains("f"));
    EXPECT_EQ(out[5], out[0]);
    for (int k = 1; k <= 4; ++k) ASSERT_TRUE(out[k].contains("error")) << out[k].dump();
    EXPECT_NE(out[1]["error"].get<std::string>().find("line 2"), std::string::npos);
    EXPECT_NE(out[2]["error"].get<std::string>().find("cy"), std::string::npos);
    EXPECT_NE(out[3]["error"].get<std::string>().find("shininess"), std::string::npos);
    EXPECT_NE(out[4]["error"].get<std::string>().find("wi"), std::string::npos);
}

uint32_t bigEndian32(const unsigned char* p) { return uint32_t(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]; }

TEST(Cli, BsdfPlotWritesPngOfTheRightSize) {
    const std::string png = tempPath("lobe.png");
    std::remove(png.c_str());
    const RunResult r = runWoven("bsdf-plot --size 40 --material '{\"ex\": 50}' -o '" + png + "' 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0);
    std::ifstream f(png, std::ios::binary);
    ASSERT_TRUE(f.good());
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    ASSERT_GE(bytes.size(), 33u);
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    EXPECT_TRUE(std::equal(signature, signature + 8, bytes.begin()));
    EXPECT_EQ(std::string(bytes.begin() + 12, bytes.begin() + 16), "IHDR");
    EXPECT_EQ(bigEndian32(&bytes[16]), 80u);  // two panels, weft and warp, side by side
    EXPECT_EQ(bigEndian32(&bytes[20]), 40u);
    std::remove(png.c_str());
}

TEST(Cli, BsdfPlotBadMaterialLeavesNoFile) {
    const std::string png = tempPath("bad.png");
    std::remove(png.c_str());
    EXPECT_NE(runWoven("bsdf-plot --material '{\"cy\": 3}' -o '" + png + "' 2>/dev/null").exitCode, 0);
    EXPECT_NE(runWoven("bsdf-plot --material '{oops' -o '" + png + "' 2>/dev/null").exitCode, 0);
    EXPECT_FALSE(std::ifstream(png).good());
    EXPECT_FALSE(std::ifstream(png + ".partial").good());
}

}  // namespace
}  // namespace woven
