// What a draft makes of a woven material (core/draft/draft_material.h, material_json.h): the tile,
// colours, spacing and widths per thread against values worked out from the file by hand; keys
// that override the draft; "scale": "draft"; every mistake named with its key or file.
#include <gtest/gtest.h>

#include <fstream>

#include "draft_material.h"
#include "material_json.h"
#include "temp_dir.h"
#include "wif_test_files.h"

namespace woven::test {
namespace {

using nlohmann::json;

// The 2/2 twill of twillWif() with thread properties: warp ends 3 and 4 black, the rest white,
// spacing 0.05 cm and thickness 0.04 cm (width 0.8) for every end; black weft, spacing 0.1 cm
// but 0.3 cm for pick 2, thickness 0.05 cm (widths 0.5 and 1/6).
std::string threadedTwill() {
    std::string text = replaced(twillWif(), "[WARP]\nThreads=8\nColor=1\n",
                                "[WARP]\nThreads=8\nColor=1\nUnits=Centimeters\nSpacing=0.05\nThickness=0.04\n");
    text = replaced(text, "[WEFT]\nThreads=8\nColor=2\n",
                    "[WEFT]\nThreads=8\nColor=2\nUnits=Centimeters\nSpacing=0.1\nThickness=0.05\n");
    return text + "\n[WARP COLORS]\n3=2\n4=2\n\n[WEFT SPACING]\n2=0.3\n";
}

class DraftMaterial : public ::testing::Test {
protected:
    void SetUp() override { std::ofstream(dir.file("twill.wif"), std::ios::binary) << threadedTwill(); }

    MaterialJson read(const json& j) {
        warnings.clear();
        return materialFromJson(j, WovenParams{}, dir.path().string(), warnings);
    }

    // The message of the exception materialFromJson throws for `j`.
    std::string error(const json& j) {
        try {
            read(j);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "(no error)";
    }

    TempDir dir;
    std::vector<std::string> warnings;
};

// Spacings are proportions: a draft in tiny units (2e-7 cm, in a sensible ratio) is read as the
// same cloth, not refused later as a 'warp_spacing' the user never wrote.
TEST_F(DraftMaterial, TinySpacingsKeepTheirRatios) {
    std::string text = replaced(threadedTwill(), "Spacing=0.1\nThickness=0.05", "Spacing=2e-7\nThickness=1e-7");
    text = replaced(text, "[WEFT SPACING]\n2=0.3", "[WEFT SPACING]\n2=6e-7");
    std::ofstream(dir.file("tiny.wif"), std::ios::binary) << text;
    const WovenParams p = read({{"wif", "tiny.wif"}}).params;
    ASSERT_EQ(p.weft_spacing.size(), 8u);
    EXPECT_FLOAT_EQ(p.weft_spacing[0], 0.8f);
    EXPECT_FLOAT_EQ(p.weft_spacing[1], 2.4f);
    EXPECT_NO_THROW(validate(p));
}

TEST_F(DraftMaterial, TileColoursSpacingAndWidthsPerThread) {
    const WovenParams p = read({{"wif", "twill.wif"}}).params;
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(p.tile, twillMap());
    // Warp: white but ends 3 and 4 (from 1), sRGB 255 and 0 are linear 1 and 0.
    ASSERT_EQ(p.warp_colors.size(), 8u);
    for (int end = 0; end < 8; ++end)
        EXPECT_EQ(p.warp_colors[size_t(end)], glm::vec3(end == 2 || end == 3 ? 0.0f : 1.0f)) << end;
    // Weft: every pick black, so the material's weft colour, no list.
    EXPECT_TRUE(p.weft_colors.empty());
    EXPECT_EQ(p.weft_color, glm::vec3(0.0f));
    // Even warp spacing needs no list; the weft's (0.1 cm but 0.3 cm for pick 2) keeps its ratios
    // as proportions of their mean, 0.125 cm.
    EXPECT_TRUE(p.warp_spacing.empty());
    ASSERT_EQ(p.weft_spacing.size(), 8u);
    EXPECT_FLOAT_EQ(p.weft_spacing[0], 0.8f);
    EXPECT_FLOAT_EQ(p.weft_spacing[1], 2.4f);
    // Widths: every end 0.04 / 0.05; picks 0.05 / 0.1 and, for pick 2, 0.05 / 0.3.
    EXPECT_FLOAT_EQ(p.warp_width, 0.8f);
    EXPECT_TRUE(p.warp_yarns.empty());
    ASSERT_EQ(p.yarns.size(), 2u);  // the distinct weft widths, narrowest first
    EXPECT_FLOAT_EQ(p.yarns[0].value[kYarnWidth], 0.05f / 0.3f);
    EXPECT_FLOAT_EQ(p.yarns[1].value[kYarnWidth], 0.5f);
    for (const YarnSpec& yarn : p.yarns)
        for (int f = 0; f < kYarnFieldCount; ++f) EXPECT_EQ(yarn.set[size_t(f)], f == kYarnWidth);  // the rest follows the weft
    EXPECT_EQ(p.weft_yarns, (std::vector<int>{1, 0, 1, 1, 1, 1, 1, 1}));
    validate(p);
}

TEST_F(DraftMaterial, OtherKeysOverrideTheDraft) {
    const WovenParams p = read({{"wif", "twill.wif"}, {"ex", 50}, {"weft_colors", {{1, 0, 0}}}, {"repeat", {30, 30}}}).params;
    EXPECT_EQ(p.tile, twillMap());
    EXPECT_EQ(p.ex, 50.0f);
    EXPECT_EQ(p.weft_colors, (std::vector<glm::vec3>{{1, 0, 0}}));
    EXPECT_EQ(p.repeat, glm::vec2(30.0f));
    // A material that gives its own width keeps it: the draft's thickness is not used for that
    // side. yarn_width is the weft's only: the warp keeps the draft's 0.8, though warp_width
    // follows yarn_width where no draft says otherwise.
    const WovenParams own = read({{"wif", "twill.wif"}, {"yarn_width", 0.9}}).params;
    EXPECT_EQ(own.yarn_width, 0.9f);
    EXPECT_FLOAT_EQ(own.warp_width, 0.8f);
    EXPECT_TRUE(own.yarns.empty());
    EXPECT_TRUE(own.weft_yarns.empty());
    // Likewise weft_color does not carry over to the warp colour the draft gives (white for
    // every end of twillWif()).
    std::ofstream(dir.file("white.wif"), std::ios::binary) << twillWif();
    const WovenParams red = read({{"wif", "white.wif"}, {"weft_color", {1, 0, 0}}}).params;
    EXPECT_EQ(red.weft_color, glm::vec3(1, 0, 0));
    EXPECT_EQ(red.warp_color, glm::vec3(1.0f));
    const WovenParams warpOnly = read({{"wif", "twill.wif"}, {"warp_width", 0.7}}).params;
    EXPECT_EQ(warpOnly.warp_width, 0.7f);
    EXPECT_EQ(warpOnly.weft_yarns.size(), 8u);  // the weft's widths still come from the draft
    // Own yarn types replace the draft's widths on both sides.
    const WovenParams yarns = read({{"wif", "twill.wif"}, {"yarns", {{{"ex", 5}}}}, {"warp_yarns", {0}}}).params;
    EXPECT_EQ(yarns.yarns.size(), 1u);
    EXPECT_EQ(yarns.warp_yarns, (std::vector<int>{0}));
    EXPECT_TRUE(yarns.weft_yarns.empty());
    EXPECT_EQ(yarns.warp_width, WovenParams{}.warp_width);
}

TEST_F(DraftMaterial, ScaleDraftGivesThreadsPerCentimetre) {
    // Warp: 8 ends over 8 x 0.05 cm, 20 per cm. Weft: 8 picks over 7 x 0.1 + 0.3 = 1 cm.
    const MaterialJson m = read({{"wif", "twill.wif"}, {"scale", "draft"}});
    ASSERT_TRUE(m.threadsPerCm.has_value());
    EXPECT_FLOAT_EQ(m.threadsPerCm->x, 20.0f);
    EXPECT_FLOAT_EQ(m.threadsPerCm->y, 8.0f);
    EXPECT_EQ(m.wif, dir.file("twill.wif"));
    EXPECT_FALSE(read({{"wif", "twill.wif"}}).threadsPerCm.has_value());
    // Inches: 0.02 in is 0.0508 cm.
    std::ofstream(dir.file("inches.wif"), std::ios::binary)
        << replaced(threadedTwill(), "Units=Centimeters\nSpacing=0.05", "Units=Inches\nSpacing=0.02");
    EXPECT_NEAR(read({{"wif", "inches.wif"}, {"scale", "draft"}}).threadsPerCm->x, 1.0 / 0.0508, 1e-4);
}

TEST_F(DraftMaterial, MistakesNameTheKeyOrTheFile) {
    EXPECT_EQ(error({{"wif", 3}}), "'wif' must be the path of a WIF file");
    EXPECT_NE(error({{"wif", "missing.wif"}}).find(dir.file("missing.wif") + ": no such file"), std::string::npos);
    EXPECT_EQ(error({{"scale", "draft"}}), "'scale': \"draft\" needs a draft: give \"wif\"");
    EXPECT_NE(error({{"wif", "twill.wif"}, {"scale", "real"}}).find("'scale' must be \"draft\""), std::string::npos);
    EXPECT_NE(error({{"wif", "twill.wif"}, {"scale", "draft"}, {"repeat", {1, 1}}}).find("'scale'"), std::string::npos);
    EXPECT_NE(error({{"wif", "twill.wif"}, {"ex", "shiny"}}).find("'ex' must be a number"), std::string::npos);
    // No spacing: threads per cm unknown, named with the file.
    std::ofstream(dir.file("plain.wif"), std::ios::binary) << plainLiftplanWif();
    EXPECT_EQ(error({{"wif", "plain.wif"}, {"scale", "draft"}}),
              dir.file("plain.wif") + ": the draft gives no warp spacing, so its threads per centimetre are unknown");
    // A broken draft: the reader's message, which names the file and what is missing.
    std::ofstream(dir.file("broken.wif"), std::ios::binary) << replaced(plainLiftplanWif(), "[LIFTPLAN]", "[NOTES]");
    EXPECT_NE(error({{"wif", "broken.wif"}}).find(dir.file("broken.wif")), std::string::npos);
}

TEST_F(DraftMaterial, ThicknessBeyondSpacingFillsTheCellWithAWarning) {
    std::ofstream(dir.file("thick.wif"), std::ios::binary)
        << replaced(threadedTwill(), "Spacing=0.05\nThickness=0.04", "Spacing=0.05\nThickness=0.06");
    const WovenParams p = read({{"wif", "thick.wif"}}).params;
    EXPECT_EQ(p.warp_width, 1.0f);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], dir.file("thick.wif") + ": 8 warp threads are thicker than their spacing: their yarns fill "
                                                   "their cells (width 1)");
}

// More distinct widths than yarn types: rounded to 1/255, at most kMaxYarnTypes types.
TEST(DraftMaterialWidths, ManyDistinctWidthsAreRounded) {
    Draft d;
    d.shafts = 2;
    d.warp.count = 1000;
    d.weft.count = 2;
    for (int e = 0; e < d.warp.count; ++e) {
        IndexSet shaft;
        shaft.set(size_t(e % 2));
        d.threading.push_back(shaft);
        d.warp.spacing.push_back(1.0f);
        d.warp.thickness.push_back(0.001f + 0.998f * e / 999.0f);
    }
    d.liftplan = {IndexSet(1), IndexSet(2)};
    std::vector<std::string> warnings;
    const WovenParams p = applyDraft(d, "many.wif", WovenParams{}, DraftWidths{}, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "many.wif: 1000 different yarn widths, more than woven's 256 yarn types: widths rounded to 1/255");
    EXPECT_LE(p.yarns.size(), size_t(kMaxYarnTypes));
    for (int e = 0; e < d.warp.count; ++e)
        EXPECT_NEAR(p.yarns[size_t(p.warp_yarns[size_t(e)])].value[kYarnWidth], d.warp.thickness[size_t(e)], 0.5 / 255 + 1e-6);
    validate(p);
}

}  // namespace
}  // namespace woven::test
