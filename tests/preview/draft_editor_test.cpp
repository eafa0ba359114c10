// The window's draft editor without a window (draft_editor.h, draft_view.h's layout and clicks,
// material_file.h with a draft): every edit against the drawdown worked out by hand, the
// material it makes, and saving the material with its draft and reading it back.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>

#include "draft_view.h"
#include "drawdown.h"
#include "flat_cloth.h"
#include "gl_test_context.h"
#include "material_file.h"
#include "srgb.h"
#include "temp_dir.h"
#include "woven_params_json.h"

namespace woven {
namespace {

DraftEditor houndstooth() {
    std::vector<std::string> warnings;
    DraftEditor editor = DraftEditor::open(std::string(WOVEN_ASSETS_DIR) + "/drafts/houndstooth.wif", warnings);
    EXPECT_TRUE(warnings.empty());
    return editor;
}

std::vector<std::string> drawdown(const DraftEditor& editor) {
    std::vector<std::string> rows;
    for (int pick = 0; pick < editor.draft().picks(); ++pick) {
        rows.emplace_back();
        for (int end = 0; end < editor.draft().ends(); ++end) rows.back() += editor.warpOnTop(end, pick) ? '|' : '-';
    }
    return rows;
}

const std::vector<std::string> kTwill = {"||--||--", "-||--||-", "--||--||", "|--||--|",
                                         "||--||--", "-||--||-", "--||--||", "|--||--|"};

TEST(DraftEditor, ToggledCellsChangeTheDrawdownAsWorkedOut) {
    // The houndstooth: 2/2 twill, straight draw on 4 shafts, treadle t lifts t and t + 1.
    DraftEditor editor = houndstooth();
    ASSERT_EQ(drawdown(editor), kTwill);
    // End 1 (from 0) off shaft 1: it is never lifted, so weft over it in every pick.
    editor.toggleThreading(1, 1);
    std::vector<std::string> expected = kTwill;
    for (std::string& row : expected) row[1] = '-';
    EXPECT_EQ(drawdown(editor), expected);
    editor.toggleThreading(1, 1);  // back
    // Treadle 0 (picks 0 and 4) lifts shaft 2 besides 0 and 1: only the ends on shaft 3 stay down.
    editor.toggleTieup(0, 2);
    expected = kTwill;
    expected[0] = expected[4] = "|||-|||-";
    EXPECT_EQ(drawdown(editor), expected);
    editor.toggleTieup(0, 2);
    // Pick 3 also presses treadle 1 (shafts 1, 2): every end but those on shaft 0 rises.
    editor.toggleTreadling(3, 1);
    expected = kTwill;
    expected[3] = "||||||||";
    EXPECT_EQ(drawdown(editor), expected);
    // The drawdown the model gets is the same.
    EXPECT_EQ(editor.material(WovenParams{}).tile, expected);
    EXPECT_THROW(editor.toggleLiftplan(0, 0), std::logic_error);  // driven by its tie-up
}

TEST(DraftEditor, ALiftPlanKeptBesideTheTieupFollowsIt) {
    DraftEditor editor = houndstooth();
    Draft d = editor.draft();
    for (int pick = 0; pick < d.picks(); ++pick) d.liftplan.push_back(shedOf(d, pick));
    DraftEditor both(d, "both");
    both.toggleTieup(2, 0);
    for (int pick = 0; pick < d.picks(); ++pick) EXPECT_EQ(both.draft().liftplan[size_t(pick)], shedOf(both.draft(), pick)) << pick;
    EXPECT_TRUE(both.draft().liftplan[2][0]);  // pick 2 presses treadle 2, which now lifts shaft 0 too
}

TEST(DraftEditor, LiftPlanCellsOfAnUntreadledDraft) {
    std::vector<std::string> warnings;
    DraftEditor gingham = DraftEditor::open(std::string(WOVEN_ASSETS_DIR) + "/drafts/gingham.wif", warnings);
    EXPECT_TRUE(gingham.warpOnTop(0, 0));  // plain weave: pick 0 lifts shaft 0, end 0's
    gingham.toggleLiftplan(0, 1);          // and now shaft 1 too: every end rises in pick 0
    for (int end = 0; end < gingham.draft().ends(); ++end) EXPECT_TRUE(gingham.warpOnTop(end, 0)) << end;
    EXPECT_FALSE(gingham.warpOnTop(0, 1));
}

TEST(DraftEditor, ColoursPerThreadAndPerStripe) {
    DraftEditor editor = houndstooth();
    const glm::vec3 dark = editor.draft().warp.colors[0], light = editor.draft().warp.colors[4];
    EXPECT_EQ(editor.stripe(DraftSide::Warp, 2), std::make_pair(0, 3));
    EXPECT_EQ(editor.stripe(DraftSide::Weft, 5), std::make_pair(4, 7));
    const glm::vec3 red(0.8f, 0.05f, 0.05f);
    editor.setStripeColor(DraftSide::Warp, 2, red, glm::vec3(0.5f));
    for (int end = 0; end < 8; ++end) EXPECT_EQ(editor.color(DraftSide::Warp, end, glm::vec3(0.5f)), end < 4 ? red : light);
    editor.setColor(DraftSide::Weft, 5, red, glm::vec3(0.5f));  // the weft is 4 dark, 4 light too
    EXPECT_EQ(editor.draft().weft.colors[5], red);
    EXPECT_EQ(editor.draft().weft.colors[4], light);
    EXPECT_EQ(editor.draft().weft.colors[3], dark);
    EXPECT_EQ(editor.stripe(DraftSide::Weft, 4), std::make_pair(4, 4));
    // The material: per-end colours as the draft now has them.
    const WovenParams p = editor.material(WovenParams{});
    ASSERT_EQ(p.warp_colors.size(), 8u);
    EXPECT_EQ(p.warp_colors[0], red);
    EXPECT_EQ(p.weft_colors[5], red);

    // A draft without colours starts every thread of the side from the material's colour.
    std::vector<std::string> warnings;
    Draft bare = editor.draft();
    bare.weft.colors.clear();
    DraftEditor plain(bare, "bare");
    const glm::vec3 materialWeft(0.2f, 0.3f, 0.4f);
    EXPECT_EQ(plain.stripe(DraftSide::Weft, 3), std::make_pair(0, 7));  // all alike
    plain.setColor(DraftSide::Weft, 3, red, materialWeft);
    ASSERT_EQ(plain.draft().weft.colors.size(), 8u);
    EXPECT_EQ(plain.draft().weft.colors[3], red);
    EXPECT_EQ(plain.draft().weft.colors[2], materialWeft);
}

TEST(DraftEditor, MoreThreadsRepeatTheDraft) {
    DraftEditor editor = houndstooth();
    editor.setThreadCount(DraftSide::Warp, 12);
    editor.setThreadCount(DraftSide::Weft, 10);
    const Draft& d = editor.draft();
    ASSERT_EQ(d.ends(), 12);
    ASSERT_EQ(d.picks(), 10);
    validate(d, "grown");
    for (int end = 8; end < 12; ++end) {
        EXPECT_EQ(d.threading[size_t(end)], d.threading[size_t(end - 8)]);
        EXPECT_EQ(d.warp.colors[size_t(end)], d.warp.colors[size_t(end - 8)]);
        EXPECT_EQ(d.warp.spacing[size_t(end)], d.warp.spacing[size_t(end - 8)]);
    }
    EXPECT_EQ(d.treadling[9], d.treadling[1]);
    editor.setThreadCount(DraftSide::Warp, 3);
    EXPECT_EQ(editor.draft().ends(), 3);
    validate(editor.draft(), "shrunk");
    EXPECT_THROW(editor.setThreadCount(DraftSide::Weft, 0), std::invalid_argument);
}

TEST(DraftLayout, ClicksLandOnTheCellsDrawnThere) {
    DraftEditor editor = houndstooth();  // 8 ends, 8 picks, 4 shafts, 4 treadles
    const DraftLayout layout(editor.draft(), 10.0f);
    // Rows: warp colours at y 0-10, threading (shaft 4 at the top) from 20, drawdown from 70.
    // Columns: ends from x 0, tie-up and treadling from 90, weft colours from 140.
    EXPECT_EQ(layout.size(), glm::vec2(150.0f, 150.0f));
    using R = DraftLayout::Region;
    struct Case { glm::vec2 at; R region; int column, row; };
    const Case cases[] = {
        {{25, 5}, R::WarpColors, 2, 0},  {{25, 55}, R::Threading, 2, 3},   {{95, 25}, R::Tieup, 0, 0},
        {{75, 105}, R::Drawdown, 7, 3},  {{115, 75}, R::Treadling, 2, 0}, {{145, 145}, R::WeftColors, 0, 7},
        {{85, 5}, R::None, 0, 0},        {{25, 65}, R::None, 0, 0},
    };
    for (const Case& c : cases) {
        const DraftLayout::Hit hit = layout.hit(c.at);
        EXPECT_EQ(hit.region, c.region) << c.at.x << "," << c.at.y;
        if (c.region == R::None) continue;
        EXPECT_EQ(hit.column, c.column) << c.at.x << "," << c.at.y;
        EXPECT_EQ(hit.row, c.row) << c.at.x << "," << c.at.y;
    }
    // Shaft 1 is the threading's bottom row: end 2's cell there is on shaft 0 (end 2 is on shaft 2).
    ThreadSelection selection;
    EXPECT_FALSE(editor.draft().threading[2][0]);
    EXPECT_TRUE(applyClick(editor, layout, layout.hit({25, 55}), selection));
    EXPECT_TRUE(editor.draft().threading[2][0]);
    // Tie-up (treadle 0, top row = shaft 3), treadling (pick 0, treadle 2): toggled.
    EXPECT_TRUE(applyClick(editor, layout, layout.hit({95, 25}), selection));
    EXPECT_TRUE(editor.draft().tieup[0][3]);
    EXPECT_TRUE(applyClick(editor, layout, layout.hit({115, 75}), selection));
    EXPECT_TRUE(editor.draft().treadling[0][2]);
    // Colour bars and the drawdown select a thread, editing nothing.
    EXPECT_FALSE(applyClick(editor, layout, layout.hit({25, 5}), selection));
    EXPECT_EQ(selection.side, DraftSide::Warp);
    EXPECT_EQ(selection.thread, 2);
    EXPECT_FALSE(applyClick(editor, layout, layout.hit({145, 145}), selection));
    EXPECT_EQ(selection.side, DraftSide::Weft);
    EXPECT_EQ(selection.thread, 7);
    const bool warp = editor.warpOnTop(7, 3);
    EXPECT_FALSE(applyClick(editor, layout, layout.hit({75, 105}), selection));
    EXPECT_EQ(selection.side, warp ? DraftSide::Warp : DraftSide::Weft);
    EXPECT_EQ(selection.thread, warp ? 7 : 3);

    // A lift-plan draft: the lift plan's columns are shafts, shaft 1 on the left.
    std::vector<std::string> warnings;
    DraftEditor gingham = DraftEditor::open(std::string(WOVEN_ASSETS_DIR) + "/drafts/gingham.wif", warnings);
    const DraftLayout lift(gingham.draft(), 10.0f);  // 16 ends, 2 shafts: lift plan from x 170, y 50
    const DraftLayout::Hit hit = lift.hit({185, 55});
    ASSERT_EQ(hit.region, R::Liftplan);
    EXPECT_EQ(lift.shaftOf(hit), 1);
    EXPECT_TRUE(applyClick(gingham, lift, hit, selection));
    EXPECT_TRUE(gingham.draft().liftplan[0][1]);
}

TEST(DraftEditor, MaterialSavedWithItsDraftReadsBackTheSame) {
    const test::TempDir dir;
    DraftEditor editor = houndstooth();
    // A colour a WIF file holds exactly: 8-bit sRGB (the writer rounds others to 8 bits).
    const glm::vec3 wine(srgbToLinear(150 / 255.0f), srgbToLinear(20 / 255.0f), srgbToLinear(40 / 255.0f));
    editor.setStripeColor(DraftSide::Weft, 0, wine, glm::vec3(0.5f));
    WovenParams base;
    base.ex = 321.0f;
    base.weft_color = glm::vec3(0.9f, 0.1f, 0.1f);  // the draft's colours win over these
    base.repeat = glm::vec2(40.0f);
    const WovenParams p = editor.material(base);
    const std::string path = dir.file("cloth.json");
    const std::string wif = saveMaterialWithDraft(path, "cloth", p, "", editor);
    EXPECT_EQ(wif, dir.file("cloth.wif"));
    EXPECT_EQ(editor.name(), wif);
    // The material names its draft and leaves out what the draft sets.
    std::ifstream in(path);
    const nlohmann::json saved = nlohmann::json::parse(in);
    EXPECT_EQ(saved["wif"], "cloth.wif");
    EXPECT_FALSE(saved.contains("tile"));
    EXPECT_FALSE(saved.contains("warp_colors"));
    EXPECT_EQ(saved["ex"], 321.0f);
    // Read back (from elsewhere: "wif" is relative to the material file): the same parameters.
    std::vector<std::string> warnings;
    const MaterialJson read = loadMaterial(path, "cloth", WovenParams{}, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(read.wif, wif);
    // The same cloth: every field but the sides' own colours, which the draft's per-thread colours
    // hide (a saved side colour would replace them: SCENE_FORMAT.md).
    nlohmann::json expected = paramsToJson(p), got = paramsToJson(read.params);
    for (const char* hidden : {"weft_color", "warp_color"}) expected.erase(hidden), got.erase(hidden);
    EXPECT_EQ(got, expected);
}

}  // namespace
}  // namespace woven

namespace woven::test {
namespace {

using woven::houndstooth;

// The window's path from an edit to the cloth: the same PreviewRenderer draws the material
// before and after each edit, and must draw exactly what a fresh renderer draws of the edited
// material (its textures rebuilt for whatever the edit changed: the tile, a colour, a width).
TEST(DraftEditor, EveryEditShowsInTheNextFrame) {
    ensureHeadlessGl();
    DraftEditor editor = houndstooth();
    WovenParams base;
    base.repeat = glm::vec2(12.0f);
    base.crimp = 0.4f;  // the floats texture follows the tile too
    SceneDescription scene = flatClothScene(editor.material(base));
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    const PreviewLights lights = PreviewLights::fromScene(scene);
    auto frame = [&](PreviewRenderer& r) {
        r.render(scene, lights, scene.camera, {96, 72}, PreviewOptions{});
        return r.radiance();
    };
    Image previous = frame(renderer);
    const std::function<void()> edits[] = {
        [&] { editor.toggleThreading(0, 0); },
        [&] { editor.setStripeColor(DraftSide::Warp, 5, glm::vec3(0.7f, 0.1f, 0.1f), base.warp_color); },
        [&] { editor.toggleTreadling(2, 0); },
        [&] { editor.setThreadCount(DraftSide::Weft, 12); },
    };
    for (size_t k = 0; k < std::size(edits); ++k) {
        edits[k]();
        *scene.materials[0].woven = editor.material(*scene.materials[0].woven);
        const Image next = frame(renderer);
        PreviewRenderer fresh;
        fresh.setMeshes(scene);
        EXPECT_EQ(next.pixels, frame(fresh).pixels) << "edit " << k;
        EXPECT_NE(next.pixels, previous.pixels) << "edit " << k << " did not change the frame";
        previous = next;
    }
}

}  // namespace
}  // namespace woven::test
