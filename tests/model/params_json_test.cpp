// WovenParams from and to JSON (scene files, `woven bsdf-eval`): every bad input is rejected
// with a message naming the field, fallbacks follow wovenParamTable(), and a round trip is exact.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "weave_pattern.h"
#include "woven_params_json.h"

namespace woven {
namespace {

using nlohmann::json;

// Expects paramsFromJson(text) to throw std::invalid_argument whose message names `field`.
void expectRejected(const std::string& text, const std::string& field) {
    SCOPED_TRACE(text);
    try {
        paramsFromJson(json::parse(text));
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
}

TEST(ParamsJson, RejectsUnknownKeys) {
    expectRejected(R"({"ex": 10, "exx": 5})", "exx");
    expectRejected(R"({"Cy": 0.5})", "Cy");
}

TEST(ParamsJson, RejectsNonObject) {
    EXPECT_THROW(paramsFromJson(json::parse("[1, 2]")), std::invalid_argument);
    EXPECT_THROW(paramsFromJson(json::parse("3")), std::invalid_argument);
}

TEST(ParamsJson, RejectsWrongTypes) {
    expectRejected(R"({"ex": "100"})", "ex");
    expectRejected(R"({"cy": [0.5]})", "cy");
    expectRejected(R"({"pattern": [1, 1]})", "pattern");
    expectRejected(R"({"pattern": [1.5, 1, 1]})", "pattern");
    expectRejected(R"({"pattern": 3})", "pattern");
    expectRejected(R"({"repeat": [1, 2, 3]})", "repeat");
    expectRejected(R"({"weft_color": [0.1, 0.2]})", "weft_color");
    expectRejected(R"({"weft_color": [0.1, "a", 0.2]})", "weft_color");
    expectRejected(R"({"backing": 0.5})", "backing");
    expectRejected(R"({"tile": "-|"})", "tile");
    expectRejected(R"({"tile": ["-|", 3]})", "tile");
}

TEST(ParamsJson, RejectsOutOfRangeValues) {
    expectRejected(R"({"cy": 1.5})", "cy");
    expectRejected(R"({"cy": -0.1})", "cy");
    expectRejected(R"({"ex": 200000})", "ex");
    expectRejected(R"({"warp_ey": -1})", "warp_ey");
    expectRejected(R"({"rs": 2})", "rs");
    expectRejected(R"({"yarn_width": 0})", "yarn_width");
    expectRejected(R"({"noise": 1e40})", "noise");  // overflows float to inf
    expectRejected(R"({"backing": 2})", "backing");
    expectRejected(R"({"weft_color": [0.1, 1.2, 0.3]})", "weft_color");
    expectRejected(R"({"pattern": [-1, 1, 1]})", "pattern");
    expectRejected(R"({"pattern": [0, 0, 1]})", "pattern");
    expectRejected(R"({"tile": ["-|", "-"]})", "tile");
    expectRejected(R"({"tile": ["-x"]})", "tile");
}

// Integers that do not fit an int must not wrap into a valid value (4294967297 -> 1).
TEST(ParamsJson, RejectsIntegersBeyondIntRange) {
    expectRejected(R"({"pattern": [4294967297, 1, 1]})", "pattern");
    expectRejected(R"({"pattern": [1, 1, -4294967295]})", "pattern");
    expectRejected(R"({"pattern": [1, 18446744073709551615, 1]})", "pattern");
    expectRejected(R"({"backing": 4294967297})", "backing");
}

TEST(ParamsJson, AbsentFieldsKeepBase) {
    WovenParams base;
    base.cy = 0.25f;
    base.rs = 0.5f;
    WovenParams p = paramsFromJson(json::parse(R"({"rs": 0.1})"), base);
    EXPECT_EQ(p.cy, 0.25f);
    EXPECT_EQ(p.rs, 0.1f);
}

TEST(ParamsJson, WarpFollowsWeftWhenAbsent) {
    WovenParams p = paramsFromJson(json::parse(
        R"({"ex": 7, "ey": 3, "weft_color": [0.1, 0.2, 0.3], "yarn_width": 0.6})"));
    EXPECT_EQ(p.warp_ex, 7.0f);
    EXPECT_EQ(p.warp_ey, 3.0f);
    EXPECT_EQ(p.warp_color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(p.warp_width, 0.6f);
}

TEST(ParamsJson, ExplicitWarpWinsOverFallback) {
    WovenParams p = paramsFromJson(json::parse(
        R"({"ex": 7, "warp_ex": 40, "ey": 3, "warp_ey": 9, "yarn_width": 0.6, "warp_width": 0.9})"));
    EXPECT_EQ(p.ex, 7.0f);
    EXPECT_EQ(p.warp_ex, 40.0f);
    EXPECT_EQ(p.ey, 3.0f);
    EXPECT_EQ(p.warp_ey, 9.0f);
    EXPECT_EQ(p.warp_width, 0.9f);
    // The order of keys in the file must not matter.
    WovenParams q = paramsFromJson(json::parse(R"({"warp_ex": 40, "ex": 7})"));
    EXPECT_EQ(q.warp_ex, 40.0f);
    EXPECT_EQ(q.ex, 7.0f);
}

TEST(ParamsJson, GreyShorthandForColours) {
    WovenParams p = paramsFromJson(json::parse(R"({"weft_color": 0.3, "backing_color": 0.7})"));
    EXPECT_EQ(p.weft_color, glm::vec3(0.3f));
    EXPECT_EQ(p.warp_color, glm::vec3(0.3f));  // fallback from weft_color
    EXPECT_EQ(p.backing_color, glm::vec3(0.7f));
    expectRejected(R"({"weft_color": 1.5})", "weft_color");
    // A single number is not a shorthand for a Vec2.
    expectRejected(R"({"repeat": 4})", "repeat");
}

TEST(ParamsJson, TileRowsReplaceThePattern) {
    WovenParams p = paramsFromJson(json::parse(R"({"tile": ["--|", "|--", "-|-"]})"));
    ASSERT_EQ(p.tile.size(), 3u);
    EXPECT_EQ(p.tile[0], "--|");
    EXPECT_EQ(p.tile[2], "-|-");
    WeavePattern w = WeavePattern::fromParams(p);
    EXPECT_EQ(w.draw(6, 3), "--|--|\n|--|--\n-|--|-\n");
}

TEST(ParamsJson, RoundTripIsExact) {
    WovenParams p;
    p.pattern = {9, 1, 3};
    p.repeat = {37.5f, 12.25f};
    p.ex = 1234.5f;
    p.ey = 0.0f;
    p.warp_ex = 3.3f;
    p.warp_ey = 99999.0f;
    p.rs = 0.123f;
    p.weft_color = {0.1f, 0.2f, 0.3f};
    p.warp_color = {0.9f, 0.8f, 0.7f};
    p.cy = 0.77f;
    p.yarn_width = 0.31f;
    p.warp_width = 0.62f;
    p.crimp = 0.4f;
    p.noise = 0.6f;
    p.noise_scale = 3.7f;
    p.backing = 1;
    p.backing_color = {0.05f, 0.06f, 0.07f};
    p.tile = {"-||", "|-|"};
    WovenParams q = paramsFromJson(paramsToJson(p));
    EXPECT_EQ(q.pattern, p.pattern);
    EXPECT_EQ(q.tile, p.tile);
    EXPECT_EQ(q.repeat, p.repeat);
    EXPECT_EQ(q.ex, p.ex);
    EXPECT_EQ(q.ey, p.ey);
    EXPECT_EQ(q.warp_ex, p.warp_ex);
    EXPECT_EQ(q.warp_ey, p.warp_ey);
    EXPECT_EQ(q.rs, p.rs);
    EXPECT_EQ(q.weft_color, p.weft_color);
    EXPECT_EQ(q.warp_color, p.warp_color);
    EXPECT_EQ(q.cy, p.cy);
    EXPECT_EQ(q.yarn_width, p.yarn_width);
    EXPECT_EQ(q.warp_width, p.warp_width);
    EXPECT_EQ(q.crimp, p.crimp);
    EXPECT_EQ(q.noise, p.noise);
    EXPECT_EQ(q.noise_scale, p.noise_scale);
    EXPECT_EQ(q.backing, p.backing);
    EXPECT_EQ(q.backing_color, p.backing_color);
    // And through text, as a scene file stores it.
    WovenParams r = paramsFromJson(json::parse(paramsToJson(p).dump()));
    EXPECT_EQ(r.ex, p.ex);
    EXPECT_EQ(r.weft_color, p.weft_color);
    EXPECT_EQ(r.noise_scale, p.noise_scale);
}

TEST(ParamsJson, PerThreadListsRoundTrip) {
    const json j = json::parse(R"({
        "warp_colors": [[0.1, 0.2, 0.3], 0.5],
        "weft_colors": [[1, 0, 0]],
        "yarns": [{"ex": 300, "yarn_width": 0.6}, {"noise": 0.2, "cy": 1}],
        "warp_yarns": [0, 1, 1],
        "weft_yarns": [1],
        "warp_spacing": [1, 2],
        "weft_spacing": [0.5]
    })");
    const WovenParams p = paramsFromJson(j);
    ASSERT_EQ(p.warp_colors.size(), 2u);
    EXPECT_EQ(p.warp_colors[1], glm::vec3(0.5f));
    ASSERT_EQ(p.yarns.size(), 2u);
    EXPECT_TRUE(p.yarns[0].set[kYarnEx] && p.yarns[0].set[kYarnWidth]);
    EXPECT_FALSE(p.yarns[0].set[kYarnCy]);
    EXPECT_EQ(p.yarns[1].value[kYarnCy], 1.0f);
    EXPECT_EQ(p.warp_yarns, (std::vector<int>{0, 1, 1}));
    EXPECT_EQ(p.warp_spacing, (std::vector<float>{1.0f, 2.0f}));
    const WovenParams q = paramsFromJson(json::parse(paramsToJson(p).dump()));
    EXPECT_EQ(q.warp_colors, p.warp_colors);
    EXPECT_EQ(q.weft_colors, p.weft_colors);
    EXPECT_EQ(q.yarns, p.yarns);
    EXPECT_EQ(q.warp_yarns, p.warp_yarns);
    EXPECT_EQ(q.weft_yarns, p.weft_yarns);
    EXPECT_EQ(q.warp_spacing, p.warp_spacing);
    EXPECT_EQ(q.weft_spacing, p.weft_spacing);
    // A material without lists writes none.
    EXPECT_FALSE(paramsToJson(WovenParams{}).contains("warp_colors"));
}

TEST(ParamsJson, PerThreadErrorsNameTheKeyAndTheEntry) {
    expectRejected(R"({"warp_colors": 0.5})", "'warp_colors' must be an array of colours");
    expectRejected(R"({"warp_colors": [0.1, [0.1, 1.2, 0.3]]})", "'warp_colors'[1] = 1.2 is outside [0, 1]");
    expectRejected(R"({"weft_colors": [[0.1, 0.2]]})", "'weft_colors'[0] must be an array of 3 numbers");
    expectRejected(R"({"warp_yarns": [0]})", "'warp_yarns'[0] = 0 names no yarn type ('yarns' has 0)");
    expectRejected(R"({"yarns": [{"ex": 1}], "weft_yarns": [0, 1]})", "'weft_yarns'[1] = 1 names no yarn type");
    expectRejected(R"({"yarns": [{}, {}], "warp_yarns": [1.5]})", "'warp_yarns'[0] must be an integer");
    expectRejected(R"({"yarns": [{"exx": 1}]})", "'yarns'[0]: unknown yarn field 'exx'");
    expectRejected(R"({"yarns": [{"warp_ex": 1}]})", "unknown yarn field 'warp_ex'");  // a yarn has one ex
    expectRejected(R"({"yarns": [{}, {"yarn_width": 0}]})", "'yarns'[1].yarn_width = 0 is outside");
    expectRejected(R"({"yarns": [3]})", "'yarns'[0] must be an object");
    expectRejected(R"({"warp_spacing": [1, -2]})", "'warp_spacing'[1] = -2 is outside");
    expectRejected(R"({"weft_spacing": [1, "a"]})", "'weft_spacing'[1] must be a number");
    // 256 colours and 257 spacings repeat together every 65792 threads, beyond the limit.
    json j = {{"warp_colors", json::array()}, {"warp_spacing", json::array()}};
    for (int k = 0; k < 256; ++k) j["warp_colors"].push_back(0.5);
    for (int k = 0; k < 257; ++k) j["warp_spacing"].push_back(1.0);
    expectRejected(j.dump(), "repeat together only every 65792 threads");
}

}  // namespace
}  // namespace woven
