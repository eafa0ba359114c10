// The drafts in assets/drafts (written by tools/make_drafts): they read without a warning,
// hold the weave and colours their names promise, and are exactly what woven's writer writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>
#include <tuple>

#include "image_io.h"
#include "wif_reader.h"
#include "wif_test_files.h"
#include "wif_writer.h"

namespace woven {
namespace {

Draft readAsset(const std::string& name, std::string* text = nullptr) {
    const std::string path = std::string(WOVEN_ASSETS_DIR) + "/drafts/" + name;
    std::vector<std::string> warnings;
    const Draft draft = readWif(path, warnings);
    EXPECT_TRUE(warnings.empty()) << name << ": " << (warnings.empty() ? "" : warnings.front());
    if (text) {
        std::ifstream in(path, std::ios::binary);
        *text = std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return draft;
}

size_t distinctColours(const std::vector<glm::vec3>& colours) {
    std::set<std::tuple<float, float, float>> distinct;
    for (const glm::vec3& c : colours) distinct.insert({c.x, c.y, c.z});
    return distinct.size();
}

// Warp and weft on top alternately in 2 x 2 blocks shifting by one each pick: 2/2 twill.
bool isTwoTwoTwill(const std::vector<std::string>& map) {
    for (size_t V = 0; V < map.size(); ++V)
        for (size_t U = 0; U < map[V].size(); ++U)
            if ((map[V][U] == '|') != ((U + 4 - V % 4) % 4 < 2)) return false;
    return true;
}

TEST(DraftAssets, HoundstoothIsATwoTwoTwillWithFourAndFourColours) {
    std::string text;
    const Draft d = readAsset("houndstooth.wif", &text);
    EXPECT_EQ(formatWif(d, "houndstooth"), text);
    EXPECT_EQ(d.shafts, 4);
    EXPECT_TRUE(d.usesTieup());
    EXPECT_TRUE(isTwoTwoTwill(test::mapOf(d)));
    ASSERT_EQ(d.warp.colors.size(), 8u);
    EXPECT_EQ(distinctColours(d.warp.colors), 2u);
    for (int e = 0; e < 8; ++e) EXPECT_EQ(d.warp.colors[size_t(e)], d.warp.colors[size_t(e / 4 * 4)]);
    EXPECT_NE(d.warp.colors[0], d.warp.colors[4]);
    EXPECT_EQ(d.weft.colors, d.warp.colors);
}

TEST(DraftAssets, GinghamIsAPlainWeaveInStripesByLiftPlan) {
    std::string text;
    const Draft d = readAsset("gingham.wif", &text);
    EXPECT_EQ(formatWif(d, "gingham"), text);
    EXPECT_FALSE(d.usesTieup());
    EXPECT_EQ(d.treadles, 0);
    const std::vector<std::string> map = test::mapOf(d);
    for (size_t V = 0; V < map.size(); ++V)
        for (size_t U = 0; U < map[V].size(); ++U) EXPECT_EQ(map[V][U] == '|', (U + V) % 2 == 0);
    EXPECT_EQ(distinctColours(d.warp.colors), 2u);
    EXPECT_EQ(d.weft.colors, d.warp.colors);
}

TEST(DraftAssets, TwillWithStripesHasThickerStripeThreads) {
    std::string text;
    const Draft d = readAsset("twill_stripes.wif", &text);
    EXPECT_EQ(formatWif(d, "twill_stripes"), text);
    EXPECT_TRUE(isTwoTwoTwill(test::mapOf(d)));
    EXPECT_EQ(d.warp.units, LengthUnit::Inches);
    EXPECT_EQ(distinctColours(d.warp.colors), 3u);
    EXPECT_EQ(distinctColours(d.weft.colors), 1u);
    ASSERT_EQ(d.warp.thickness.size(), size_t(d.ends()));
    ASSERT_EQ(d.warp.spacing.size(), size_t(d.ends()));
    for (int e = 0; e < d.ends(); ++e) {
        const bool stripe = d.warp.colors[size_t(e)] != d.warp.colors[0];
        EXPECT_EQ(d.warp.thickness[size_t(e)] > d.warp.thickness[0], stripe) << e;
        EXPECT_EQ(d.warp.spacing[size_t(e)] > d.warp.spacing[0], stripe) << e;
        EXPECT_LE(d.warp.thickness[size_t(e)], d.warp.spacing[size_t(e)]) << e;  // no yarn wider than its cell
    }
}

// tools/make_drafts writes denim.wif (the default scene's cloth): a warp-faced 3/1 twill, indigo
// ends and ecru picks, 25 ends and 16 picks per cm.
TEST(DraftAssets, DenimIsAWarpFacedThreeOneTwillAtItsThreadCounts) {
    std::string text;
    const Draft d = readAsset("denim.wif", &text);
    EXPECT_EQ(formatWif(d, "denim"), text);
    const std::vector<std::string> map = test::mapOf(d);
    ASSERT_EQ(map.size(), 4u);
    for (size_t V = 0; V < map.size(); ++V) {
        ASSERT_EQ(map[V].size(), 4u);
        EXPECT_EQ(std::count(map[V].begin(), map[V].end(), '|'), 3) << "pick " << V;  // 3 up, 1 down
        EXPECT_EQ(map[V], map[0].substr(4 - V % 4) + map[0].substr(0, 4 - V % 4)) << "pick " << V;  // the diagonal
    }
    EXPECT_EQ(distinctColours(d.warp.colors), 1u);
    EXPECT_EQ(distinctColours(d.weft.colors), 1u);
    EXPECT_NE(d.warp.colors[0], d.weft.colors[0]);
    EXPECT_EQ(d.warp.units, LengthUnit::Centimeters);
    EXPECT_FLOAT_EQ(1.0f / d.warp.spacing[0], 25.0f);
    EXPECT_FLOAT_EQ(1.0f / d.weft.spacing[0], 16.0f);
}

}  // namespace
}  // namespace woven
