// The drawdown of drafts built here against maps drawn by hand (plain weave, 2/2 twill, a
// point twill), what draftTile() hands the model, and the drawdown picture.
#include <gtest/gtest.h>

#include "draft_tile.h"
#include "drawdown.h"
#include "drawdown_image.h"
#include "wif_test_files.h"

namespace woven {
namespace {

IndexSet setOf(std::initializer_list<int> members) {
    IndexSet set;
    for (int m : members) set.set(size_t(m));
    return set;
}

// A draft with `shafts` shafts, end e threaded on threading[e] (0-based shafts), and pick p
// lifting lifts[p]; `tieup` + `treadling` instead when given.
Draft draftOf(int shafts, const std::vector<int>& threading, const std::vector<std::vector<int>>& lifts) {
    Draft d;
    d.shafts = shafts;
    d.warp.count = int(threading.size());
    d.weft.count = int(lifts.size());
    for (int shaft : threading) d.threading.push_back(setOf({shaft}));
    for (const auto& lift : lifts) {
        IndexSet set;
        for (int shaft : lift) set.set(size_t(shaft));
        d.liftplan.push_back(set);
    }
    return d;
}

TEST(Drawdown, PlainWeaveMatchesTheHandDrawnMap) {
    const Draft plain = draftOf(2, {0, 1, 0, 1, 0, 1}, {{0}, {1}, {0}, {1}});
    EXPECT_EQ(test::mapOf(plain), (std::vector<std::string>{"|-|-|-", "-|-|-|", "|-|-|-", "-|-|-|"}));
}

TEST(Drawdown, TwoTwoTwillByTieupMatchesTheHandDrawnMap) {
    // Straight draw on 4 shafts, treadles tied 12 23 34 41, treadled 1 2 3 4.
    Draft twill = draftOf(4, {0, 1, 2, 3, 0, 1, 2, 3}, {});
    twill.weft.count = 4;
    twill.treadles = 4;
    twill.tieup = {setOf({0, 1}), setOf({1, 2}), setOf({2, 3}), setOf({3, 0})};
    twill.treadling = {setOf({0}), setOf({1}), setOf({2}), setOf({3})};
    EXPECT_EQ(test::mapOf(twill), (std::vector<std::string>{"||--||--", "-||--||-", "--||--||", "|--||--|"}));
}

TEST(Drawdown, PointTwillMatchesTheHandDrawnMap) {
    // Point draw 1 2 3 4 3 2 on 4 shafts, 2/2 lifts: the twill line turns at the points.
    const Draft point = draftOf(4, {0, 1, 2, 3, 2, 1}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
    EXPECT_EQ(test::mapOf(point), (std::vector<std::string>{"||---|", "-||-||", "--|||-", "|--|--"}));
}

TEST(Drawdown, SinkingShedInverts) {
    Draft plain = draftOf(2, {0, 1, 0, 1}, {{0}, {1}});
    plain.risingShed = false;
    EXPECT_EQ(test::mapOf(plain), (std::vector<std::string>{"-|-|", "|-|-"}));
}

TEST(Drawdown, UnthreadedEndsAndEmptyPicksStayUnder) {
    Draft d = draftOf(2, {0, 1, 0}, {{0, 1}, {}});
    d.threading[2].reset();
    EXPECT_EQ(test::mapOf(d), (std::vector<std::string>{"||-", "---"}));
}

TEST(Drawdown, NoInterlacementIsRefused) {
    Draft d = draftOf(2, {0, 1}, {{0}, {1}});
    d.liftplan.clear();
    EXPECT_THROW(Drawdown(d, "d"), DraftError);
    EXPECT_THROW(draftTile(d, "d"), DraftError);
}

TEST(DraftTile, CarriesThreadColoursAndLengthsInCentimeters) {
    Draft d = draftOf(2, {0, 1, 0}, {{0}, {1}});
    const glm::vec3 red(1, 0, 0), green(0, 1, 0);
    d.warp.colors = {red, green, red};
    d.warp.units = LengthUnit::Decipoints;
    d.warp.spacing = {720, 360, 72};
    d.weft.units = LengthUnit::Inches;
    d.weft.thickness = {1.0f, 0.5f};
    const DraftTile tile = draftTile(d, "d");
    EXPECT_EQ(tile.warpColors, d.warp.colors);
    EXPECT_TRUE(tile.weftColors.empty());
    ASSERT_EQ(tile.warpSpacing.size(), 3u);
    EXPECT_FLOAT_EQ(tile.warpSpacing[0], 2.54f);  // 720 decipoints = 1 inch
    EXPECT_FLOAT_EQ(tile.warpSpacing[2], 0.254f);
    EXPECT_TRUE(tile.warpThickness.empty());
    ASSERT_EQ(tile.weftThickness.size(), 2u);
    EXPECT_FLOAT_EQ(tile.weftThickness[1], 1.27f);
    // The tile is what WovenParams::tile and WeavePattern take.
    const WeavePattern pattern = WeavePattern::fromRows(tile.rows);
    EXPECT_EQ(pattern.width(), 3);
    EXPECT_EQ(pattern.height(), 2);
    EXPECT_EQ(pattern.top(1, 1), YarnType::Warp);
}

TEST(DrawdownImage, EachCellHasTheColourOfTheYarnOnTop) {
    const WeavePattern weave = WeavePattern::fromRows({"|-", "--"});
    const glm::vec3 w0(1, 0, 0), w1(0, 1, 0), f0(0, 0, 1), f1(1, 1, 0);
    const Image image = drawdownImage(weave, {w0, w1}, {f0, f1}, 4, 3, 2);
    ASSERT_EQ(image.width, 8);
    ASSERT_EQ(image.height, 6);
    // Cell (U, V) covers pixels [2U, 2U + 2) x [2V, 2V + 2); the tile and the colours repeat.
    EXPECT_EQ(image.at(0, 0), w0);  // (0, 0): warp, end 0
    EXPECT_EQ(image.at(3, 1), f0);  // (1, 0): weft, pick 0
    EXPECT_EQ(image.at(5, 0), w0);  // (2, 0): warp, end 2 -> colour 0
    EXPECT_EQ(image.at(1, 3), f1);  // (0, 1): weft, pick 1
    EXPECT_EQ(image.at(4, 5), w0);  // (2, 2): tile row 0 again, warp
    EXPECT_EQ(image.at(7, 5), f0);  // (3, 2): weft, pick 2 -> colour 0
    EXPECT_THROW(drawdownImage(weave, {}, {f0}, 4, 3, 2), std::invalid_argument);
    EXPECT_THROW(drawdownImage(weave, {w0}, {f0}, 100000, 100000, 8), std::invalid_argument);
}

}  // namespace
}  // namespace woven
