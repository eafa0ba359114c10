// The WIF reader's rules (docs/DRAFTS.md), each on files written here: finding sections,
// numbering, which of tie-up and lift plan decides, the shed, colours and per-thread values,
// out-of-range values, and the errors for drafts that cannot be used.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "image_io.h"
#include "temp_dir.h"
#include "wif_reader.h"
#include "wif_test_files.h"

namespace woven {
namespace {

using test::mapOf;
using test::readText;
using test::replaced;

IndexSet setOf(std::initializer_list<int> members) {
    IndexSet set;
    for (int m : members) set.set(size_t(m));
    return set;
}

// The warnings that contain `part`.
int warningsWith(const std::vector<std::string>& warnings, const std::string& part) {
    return int(std::count_if(warnings.begin(), warnings.end(),
                             [&](const std::string& w) { return w.find(part) != std::string::npos; }));
}

std::string allOf(const std::vector<std::string>& warnings) {
    std::string all;
    for (const auto& w : warnings) all += w + "\n";
    return all;
}

// The DraftError message of reading `text` from a file called `fileName`; fails the test when
// it reads without one.
std::string errorOf(const std::string& text, const std::string& fileName = "broken.wif") {
    std::vector<std::string> warnings;
    try {
        readText(text, warnings, fileName);
    } catch (const DraftError& e) {
        EXPECT_NE(std::string(e.what()).find(fileName), std::string::npos) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "read without an error";
    return "";
}

TEST(WifReader, ReadsTheTwillDraft) {
    std::vector<std::string> warnings;
    const Draft d = readText(test::twillWif(), warnings);
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
    EXPECT_EQ(d.shafts, 4);
    EXPECT_EQ(d.treadles, 4);
    EXPECT_EQ(d.ends(), 8);
    EXPECT_EQ(d.picks(), 8);
    EXPECT_TRUE(d.risingShed);
    ASSERT_EQ(d.threading.size(), 8u);
    EXPECT_EQ(d.threading[5], setOf({1}));  // "6=2", 1-based in the file
    ASSERT_EQ(d.tieup.size(), 4u);
    EXPECT_EQ(d.tieup[3], setOf({3, 0}));  // "4=4,1"
    EXPECT_EQ(d.treadling[6], setOf({2}));
    EXPECT_TRUE(d.liftplan.empty());
    EXPECT_TRUE(d.usesTieup());
    ASSERT_EQ(d.palette.size(), 2u);
    EXPECT_EQ(d.warp.colors, std::vector<glm::vec3>(8, glm::vec3(1.0f)));
    EXPECT_EQ(d.weft.colors, std::vector<glm::vec3>(8, glm::vec3(0.0f)));
    EXPECT_TRUE(d.warp.spacing.empty());
    EXPECT_TRUE(d.weft.thickness.empty());
    EXPECT_EQ(mapOf(d), test::twillMap());
}

TEST(WifReader, SectionNamesAndKeysIgnoreCase) {
    std::string text = replaced(test::twillWif(), "[WEAVING]", "[Weaving]");
    text = replaced(text, "Shafts=4", "SHAFTS=4");
    text = replaced(text, "Rising Shed=true", "rising shed=TRUE");
    text = replaced(text, "[COLOR TABLE]", "[color table]");
    text = replaced(text, "Threads=", "tHrEaDs=");
    std::vector<std::string> warnings, baseWarnings;
    EXPECT_EQ(readText(text, warnings), readText(test::twillWif(), baseWarnings));
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
}

TEST(WifReader, CommentsStrayTextAndPrivateSectionsDoNotChangeTheDraft) {
    std::string text = "Saved by SomeWeaver 3.0\nthis line is not part of any section\n" + test::twillWif();
    text = replaced(text, "[THREADING]\n1=1\n", "[THREADING]\n; a comment\n  ;indented comment\n1=1 ; first end\n");
    // Private sections may use the same keys as standard ones; they must not leak into them.
    text += "\n[PIXELOOM SETTINGS]\nShafts=12\nThreads=3\n1=4\n[TIEUP EXTRA]\n1=1,2,3,4\n";
    text = replaced(text, "[WEAVING]", "[MY PROGRAM]\nThreads=99\n[WEAVING]");
    std::vector<std::string> warnings, baseWarnings;
    EXPECT_EQ(readText(text, warnings), readText(test::twillWif(), baseWarnings));
    // The text before [WIF] is reported once; private sections are the format's own way to
    // extend it and pass without a word.
    EXPECT_EQ(warnings.size(), 1u) << allOf(warnings);
    EXPECT_EQ(warningsWith(warnings, "2 lines of text before the first section"), 1) << allOf(warnings);
}

TEST(WifReader, ContentsIsNotTrusted) {
    // [CONTENTS] claims a lift plan and denies the tie-up; the sections say otherwise.
    const std::string text = replaced(test::twillWif(), "TIEUP=true", "TIEUP=false\nLIFTPLAN=true");
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_TRUE(d.usesTieup());
    EXPECT_TRUE(d.liftplan.empty());
    EXPECT_EQ(mapOf(d), test::twillMap());
}

TEST(WifReader, CrLfAndCrLineEndsReadTheSame) {
    std::vector<std::string> warnings;
    const Draft base = readText(test::twillWif(), warnings);
    EXPECT_EQ(readText(replaced(test::twillWif(), "\n", "\r\n"), warnings), base);
    EXPECT_EQ(readText(replaced(test::twillWif(), "\n", "\r"), warnings), base);
    EXPECT_EQ(readText("\xEF\xBB\xBF" + test::twillWif(), warnings), base);  // UTF-8 byte order mark
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
}

TEST(WifReader, Latin1TitleBecomesUtf8) {
    std::vector<std::string> warnings;
    // Windows-1252: e acute, and curly quotes in 0x93 / 0x94.
    const Draft latin = readText(test::twillWif() + "[TEXT]\nTitle=Caf\xE9 \x93Rose\x94\n", warnings);
    EXPECT_EQ(latin.title, "Caf\xC3\xA9 \xE2\x80\x9CRose\xE2\x80\x9D");
    const Draft utf8 = readText(test::twillWif() + "[TEXT]\nTitle=Caf\xC3\xA9 \xE2\x9C\x93\n", warnings);
    EXPECT_EQ(utf8.title, "Caf\xC3\xA9 \xE2\x9C\x93");
}

TEST(WifReader, EmptySectionCountsAsAbsent) {
    std::vector<std::string> warnings;
    // An empty [LIFTPLAN] beside a tie-up and treadling changes nothing.
    const Draft withEmpty = readText(test::twillWif() + "[LIFTPLAN]\n; nothing here\n\n", warnings);
    EXPECT_TRUE(withEmpty.liftplan.empty());
    EXPECT_EQ(mapOf(withEmpty), test::twillMap());
    // An empty [TIEUP] is no tie-up: with a lift plan the lift plan decides ...
    const std::string emptyTieup = replaced(test::twillWif(), "1=1,2\n2=2,3\n3=3,4\n4=4,1\n", "; cleared\n");
    const Draft byLiftplan = readText(emptyTieup + "[LIFTPLAN]\n1=1\n2=2\n3=3\n4=4\n5=1\n6=2\n7=3\n8=4\n", warnings);
    EXPECT_TRUE(byLiftplan.tieup.empty());
    EXPECT_FALSE(byLiftplan.usesTieup());
    // ... and without one there is no interlacement.
    const std::string message = errorOf(emptyTieup, "empty_tieup.wif");
    EXPECT_NE(message.find("no interlacement"), std::string::npos) << message;
    EXPECT_NE(message.find("without a [TIEUP]"), std::string::npos) << message;
    // An empty [WIF] section is no [WIF] section.
    EXPECT_NE(errorOf(replaced(test::twillWif(), "Version=1.1\nDate=April 20, 1997\nDevelopers=wif@mhsoft.com\n"
                                                 "Source Program=woven tests\n", "")).find("[WIF] section is empty"),
              std::string::npos);
}

TEST(WifReader, ThreadingEntryMayNameSeveralShafts) {
    // End 1 on shafts 1 and 3: up whenever the pick lifts either (picks 1-4 and 5-8 of the twill;
    // shaft 1 alone lifted it in picks 1, 4, 5, 8).
    const std::string text = replaced(test::twillWif(), "[THREADING]\n1=1\n", "[THREADING]\n1=1,3\n");
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.threading[0], setOf({0, 2}));
    std::vector<std::string> expected = test::twillMap();
    for (int pick : {1, 2, 5, 6}) expected[size_t(pick)][0] = '|';
    EXPECT_EQ(mapOf(d), expected);
}

TEST(WifReader, TreadlingEntryMayNameSeveralTreadles) {
    // Pick 1 presses treadles 1 and 3: shafts 1, 2, 3, 4 all rise, every end is up.
    const std::string text = replaced(test::twillWif(), "[TREADLING]\n1=1\n", "[TREADLING]\n1=1,3\n");
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.treadling[0], setOf({0, 2}));
    std::vector<std::string> expected = test::twillMap();
    expected[0] = "||||||||";
    EXPECT_EQ(mapOf(d), expected);
}

TEST(WifReader, LiftPlanOnly) {
    std::vector<std::string> warnings;
    const Draft d = readText(test::plainLiftplanWif(), warnings);
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
    EXPECT_EQ(d.treadles, 0);
    EXPECT_TRUE(d.tieup.empty());
    EXPECT_TRUE(d.treadling.empty());
    EXPECT_EQ(d.liftplan[1], setOf({1}));
    EXPECT_EQ(mapOf(d), test::plainMap());
}

TEST(WifReader, TieupAndTreadlingWinOverTheLiftPlan) {
    // A lift plan that lifts every shaft in every pick, beside the twill's tie-up and treadling.
    std::string text = test::twillWif() + "[LIFTPLAN]\n";
    for (int p = 1; p <= 8; ++p) text += std::to_string(p) + "=1,2,3,4\n";
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.liftplan.size(), 8u);  // kept, for writing back
    EXPECT_EQ(mapOf(d), test::twillMap());
    EXPECT_EQ(warnings.size(), 1u) << allOf(warnings);
    EXPECT_EQ(warningsWith(warnings, "[LIFTPLAN] differs from [TIEUP] x [TREADLING] in 8 picks"), 1) << allOf(warnings);

    // The lift plan that agrees with them, as many programs write it, passes without a warning.
    std::string agreeing = test::twillWif() + "[LIFTPLAN]\n";
    for (int p = 1; p <= 8; ++p) agreeing += std::to_string(p) + "=" + std::to_string((p - 1) % 4 + 1) + "," +
                                             std::to_string(p % 4 + 1) + "\n";
    warnings.clear();
    readText(agreeing, warnings);
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
}

TEST(WifReader, LiftPlanDecidesWhenTreadlingOrTieupIsMissing) {
    std::string liftAll = "[LIFTPLAN]\n";
    for (int p = 1; p <= 8; ++p) liftAll += std::to_string(p) + "=1,2,3,4\n";
    const std::string noTreadling = replaced(test::twillWif(), "[TREADLING]", "[OLD TREADLING]");
    std::vector<std::string> warnings;
    const Draft d = readText(noTreadling + liftAll, warnings);
    EXPECT_FALSE(d.usesTieup());
    EXPECT_EQ(d.tieup.size(), 4u);  // kept, for writing back
    EXPECT_EQ(mapOf(d), std::vector<std::string>(8, "||||||||"));
    const std::string noTieup = replaced(test::twillWif(), "[TIEUP]", "[OLD TIEUP]");
    EXPECT_EQ(mapOf(readText(noTieup + liftAll, warnings)), std::vector<std::string>(8, "||||||||"));
}

TEST(WifReader, SinkingShedInvertsTheTopYarn) {
    std::vector<std::string> warnings;
    const Draft sinking = readText(replaced(test::twillWif(), "Rising Shed=true", "Rising Shed=no"), warnings);
    EXPECT_FALSE(sinking.risingShed);
    std::vector<std::string> inverted = test::twillMap();
    for (auto& row : inverted)
        for (char& c : row) c = c == '|' ? '-' : '|';
    EXPECT_EQ(mapOf(sinking), inverted);
    // Rising Shed defaults to yes.
    const Draft unsaid = readText(replaced(test::twillWif(), "Rising Shed=true\n", ""), warnings);
    EXPECT_TRUE(unsaid.risingShed);
    EXPECT_EQ(mapOf(unsaid), test::twillMap());
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
}

TEST(WifReader, ColorTableIsRescaledByThePaletteRange) {
    struct Case { std::string range, table; glm::vec3 first, second; };
    const float half = srgbToLinear(0.5f);
    const Case cases[] = {
        {"Range=0,999", "1=999,0,499.5\n2=0,999,0", {1.0f, 0.0f, half}, {0.0f, 1.0f, 0.0f}},
        {"Range=0,65535", "1=65535,65535,0\n2=0,0,65535", {1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}},
        {"Form=RGB", "1=255,0,127.5\n2=0,0,0", {1.0f, 0.0f, half}, {0.0f, 0.0f, 0.0f}},  // no Range: 0..255
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.range);
        std::string text = replaced(test::twillWif(), "Form=RGB\nRange=0,255", c.range);
        text = replaced(text, "1=255,255,255\n2=0,0,0", c.table);
        std::vector<std::string> warnings;
        const Draft d = readText(text, warnings);
        EXPECT_TRUE(warnings.empty()) << allOf(warnings);
        ASSERT_EQ(d.palette.size(), 2u);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(d.palette[0][k], c.first[k], 1e-6f);
            EXPECT_NEAR(d.palette[1][k], c.second[k], 1e-6f);
        }
        EXPECT_EQ(d.warp.colors[0], d.palette[0]);
    }
    // A value outside the range is clamped, with a warning.
    std::vector<std::string> warnings;
    const Draft clamped = readText(replaced(test::twillWif(), "1=255,255,255", "1=300,255,255"), warnings);
    EXPECT_EQ(clamped.palette[0], glm::vec3(1.0f));
    EXPECT_EQ(warningsWith(warnings, "[COLOR TABLE]: 1 colour clamped to the Range, on line"), 1) << allOf(warnings);
    // A range that is not low,high with high > low is an error at its line.
    const std::string message = errorOf(replaced(test::twillWif(), "Range=0,255", "Range=255,0"));
    EXPECT_NE(message.find("broken.wif:20: [COLOR PALETTE] Range"), std::string::npos) << message;
}

TEST(WifReader, PerThreadListsOverrideTheWarpAndWeftDefaults) {
    std::string text = replaced(test::twillWif(), "[WARP]\nThreads=8\nColor=1\n",
                                "[WARP]\nThreads=8\nColor=1\nUnits=Decipoints\nSpacing=100\nThickness=80\n");
    text = replaced(text, "[WEFT]\nThreads=8\nColor=2\n", "[WEFT]\nThreads=8\nColor=2\nUnits=inches\nSpacing=0.05\nThickness=0.04\n");
    text = replaced(text, "Entries=2", "Entries=3");
    text = replaced(text, "2=0,0,0\n", "2=0,0,0\n3=255,0,0\n");
    text += "[WARP COLORS]\n3=3\n4=2\n[WEFT COLORS]\n8=3\n";
    text += "[WARP SPACING]\n2=200\n[WEFT SPACING]\n1=0.1\n";
    text += "[WARP THICKNESS]\n5=40\n[WEFT THICKNESS]\n2=0.02\n";
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
    const glm::vec3 white(1.0f), black(0.0f), red(1.0f, 0.0f, 0.0f);
    EXPECT_EQ(d.warp.colors, (std::vector<glm::vec3>{white, white, red, black, white, white, white, white}));
    EXPECT_EQ(d.weft.colors, (std::vector<glm::vec3>{black, black, black, black, black, black, black, red}));
    EXPECT_EQ(d.warp.units, LengthUnit::Decipoints);
    EXPECT_EQ(d.weft.units, LengthUnit::Inches);
    EXPECT_EQ(d.warp.spacing, (std::vector<float>{100, 200, 100, 100, 100, 100, 100, 100}));
    EXPECT_EQ(d.warp.thickness, (std::vector<float>{80, 80, 80, 80, 40, 80, 80, 80}));
    EXPECT_EQ(d.weft.spacing, (std::vector<float>{0.1f, 0.05f, 0.05f, 0.05f, 0.05f, 0.05f, 0.05f, 0.05f}));
    EXPECT_EQ(d.weft.thickness, (std::vector<float>{0.04f, 0.02f, 0.04f, 0.04f, 0.04f, 0.04f, 0.04f, 0.04f}));
}

TEST(WifReader, ThreadsLeftWithoutAValueTakeTheCommonOneWithAWarning) {
    // No [WARP] Color, and [WARP COLORS] names only three ends: the other five take the colour
    // most of the named ones have.
    std::string text = replaced(test::twillWif(), "[WARP]\nThreads=8\nColor=1\n", "[WARP]\nThreads=8\n");
    text += "[WARP COLORS]\n1=2\n2=2\n3=1\n";
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.warp.colors, (std::vector<glm::vec3>{glm::vec3(0), glm::vec3(0), glm::vec3(1), glm::vec3(0),
                                                     glm::vec3(0), glm::vec3(0), glm::vec3(0), glm::vec3(0)}));
    EXPECT_EQ(warningsWith(warnings, "[WARP]: 5 ends without a colour: given the colour most of the other ends have"), 1)
        << allOf(warnings);
    // A draft that gives no colour at all says nothing about colour: an empty list, no warning.
    warnings.clear();
    const Draft colourless = readText(test::plainLiftplanWif(), warnings);
    EXPECT_TRUE(colourless.warp.colors.empty());
    EXPECT_TRUE(colourless.palette.empty());
    EXPECT_TRUE(warnings.empty()) << allOf(warnings);
}

TEST(WifReader, ValuesBeyondTheDeclaredCountsAreIgnoredWithOneWarningPerSection) {
    std::string text = replaced(test::twillWif(), "[THREADING]\n1=1\n2=2\n", "[THREADING]\n1=1,9\n2=2,5\n12=1\n");
    text = replaced(text, "[TIEUP]\n1=1,2\n", "[TIEUP]\n1=1,2,7\n6=1\n");
    text = replaced(text, "[TREADLING]\n1=1\n", "[TREADLING]\n1=1,5\n9=1\n0=1\n");
    text = replaced(text, "[WEFT]\nThreads=8\nColor=2\n", "[WEFT]\nThreads=8\nColor=2\n[WEFT COLORS]\n3=7\n");
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(mapOf(d), test::twillMap());  // everything beyond was dropped, the rest stands
    EXPECT_EQ(warningsWith(warnings, "[THREADING]: 2 values ignored: beyond [WEAVING] Shafts=4, first on line"), 1)
        << allOf(warnings);
    EXPECT_EQ(warningsWith(warnings, "[THREADING]: 1 entry ignored: numbered outside 1..8 ([WARP] Threads=8)"), 1);
    EXPECT_EQ(warningsWith(warnings, "[TIEUP]: 1 value ignored: beyond [WEAVING] Shafts=4"), 1);
    EXPECT_EQ(warningsWith(warnings, "[TIEUP]: 1 entry ignored: numbered outside 1..4 ([WEAVING] Treadles=4)"), 1);
    EXPECT_EQ(warningsWith(warnings, "[TREADLING]: 1 value ignored: beyond [WEAVING] Treadles=4"), 1);
    EXPECT_EQ(warningsWith(warnings, "[TREADLING]: 2 entries ignored: numbered outside 1..8"), 1);
    EXPECT_EQ(warningsWith(warnings, "[WEFT COLORS]: 1 value ignored: names no colour of [COLOR TABLE]"), 1);
    EXPECT_EQ(warnings.size(), 7u) << allOf(warnings);
    for (const auto& w : warnings) EXPECT_NE(w.find("draft.wif: ["), std::string::npos) << w;
}

TEST(WifReader, ValuesThatAreNotNumbersAreIgnoredWithAWarning) {
    std::string text = replaced(test::twillWif(), "[THREADING]\n1=1\n", "[THREADING]\n1=1,x\nsecond=2\n");
    text = replaced(text, "Rising Shed=true", "Rising Shed=perhaps");
    text += "[WARP SPACING]\n1=-3\n2=wide\n";
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_TRUE(d.risingShed);
    EXPECT_TRUE(d.warp.spacing.empty());
    EXPECT_EQ(mapOf(d), test::twillMap());
    EXPECT_EQ(warningsWith(warnings, "[THREADING]: 1 value ignored: not a whole number >= 0"), 1) << allOf(warnings);
    EXPECT_EQ(warningsWith(warnings, "[THREADING]: 1 entry ignored: the key is not a number"), 1);
    EXPECT_EQ(warningsWith(warnings, "Rising Shed='perhaps' is not yes or no"), 1);
    EXPECT_EQ(warningsWith(warnings, "[WARP SPACING]: 2 values ignored: cannot be read"), 1);
}

TEST(WifReader, RepeatedKeysAndSectionsUseTheLastWithAWarning) {
    std::string text = replaced(test::twillWif(), "[THREADING]\n1=1\n", "[THREADING]\n1=3\n1=1\n");
    text = replaced(text, "Shafts=4", "Shafts=3\nShafts=4");
    text += "[TIEUP]\n1=1,2\n";  // a second [TIEUP] header: read as part of the first
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.shafts, 4);
    EXPECT_EQ(mapOf(d), test::twillMap());
    EXPECT_EQ(warningsWith(warnings, "Shafts is given 2 times"), 1) << allOf(warnings);
    EXPECT_EQ(warningsWith(warnings, "[THREADING]: 1 repeated number"), 1);
    EXPECT_EQ(warningsWith(warnings, "[TIEUP] appears 2 times"), 1);
}

TEST(WifReader, MissingCountsAreTakenFromTheDraftWithAWarning) {
    std::string text = replaced(test::twillWif(), "Shafts=4\nTreadles=4\n", "");
    text = replaced(text, "[WARP]\nThreads=8\n", "[WARP]\n");
    std::vector<std::string> warnings;
    const Draft d = readText(text, warnings);
    EXPECT_EQ(d.shafts, 4);
    EXPECT_EQ(d.treadles, 4);
    EXPECT_EQ(d.ends(), 8);
    EXPECT_EQ(mapOf(d), test::twillMap());
    EXPECT_EQ(warningsWith(warnings, "is missing; taking"), 3) << allOf(warnings);
}

TEST(WifReader, DraftWithoutInterlacementIsRefusedNamingTheFileAndWhatIsMissing) {
    const std::string noTreadling = replaced(test::twillWif(), "[TREADLING]", "[NOT TREADLING]");
    std::string message = errorOf(noTreadling, "no_treadling.wif");
    EXPECT_NE(message.find("no interlacement"), std::string::npos) << message;
    EXPECT_NE(message.find("no [LIFTPLAN]"), std::string::npos) << message;
    EXPECT_NE(message.find("a [TIEUP] without a [TREADLING]"), std::string::npos) << message;

    const std::string neither = replaced(noTreadling, "[TIEUP]", "[NOT TIEUP]");
    message = errorOf(neither, "threading_only.wif");
    EXPECT_NE(message.find("no [TIEUP] or [TREADLING]"), std::string::npos) << message;

    message = errorOf(replaced(test::twillWif(), "[THREADING]", "[NOT THREADING]"), "no_threading.wif");
    EXPECT_NE(message.find("no [THREADING]"), std::string::npos) << message;
}

TEST(WifReader, BrokenFilesGiveAnErrorNamingTheFile) {
    EXPECT_NE(errorOf("").find("no [WIF] section"), std::string::npos);
    EXPECT_NE(errorOf("[WEAVING]\nShafts=4\n").find("no [WIF] section"), std::string::npos);
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage += char((i * 131 + 7) % 256);
    EXPECT_NE(errorOf(garbage).find("NUL bytes"), std::string::npos);
    EXPECT_NE(errorOf(test::twillWif() + std::string(1, '\0')).find("NUL bytes"), std::string::npos);
    // Truncated in the middle of [WEAVING]: no threading, no counts for the weft.
    const std::string twill = test::twillWif();
    errorOf(twill.substr(0, twill.find("Treadles=4")));
    // A count that is not a number is an error at its line.
    const std::string message = errorOf(replaced(twill, "Shafts=4", "Shafts=four"));
    EXPECT_NE(message.find("broken.wif:23: [WEAVING] Shafts='four' is not a whole number"), std::string::npos)
        << message;
    std::vector<std::string> warnings;
    EXPECT_THROW(readWif("/nonexistent/draft.wif", warnings), DraftError);
}

TEST(WifReader, HugeDeclaredCountsAreRefusedBeforeAnythingIsSized) {
    struct Case { std::string from, to, limit; };
    const Case cases[] = {
        {"[WARP]\nThreads=8", "[WARP]\nThreads=1000000000", "[WARP] Threads=1000000000 is more than woven's limit of 65536"},
        {"[WEFT]\nThreads=8", "[WEFT]\nThreads=65537", "limit of 65536"},
        {"Shafts=4", "Shafts=257", "[WEAVING] Shafts=257 is more than woven's limit of 256"},
        {"Treadles=4", "Treadles=100000", "limit of 256"},
        {"Entries=2", "Entries=1000000000", "[COLOR PALETTE] Entries=1000000000 is more than"},
        {"[WARP]\nThreads=8", "[WARP]\nThreads=99999999999999999999999", "is not a whole number"},
        {"[WARP]\nThreads=8", "[WARP]\nThreads=-5", "must be at least 1"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.to);
        const std::string message = errorOf(replaced(test::twillWif(), c.from, c.to), "huge.wif");
        EXPECT_NE(message.find(c.limit), std::string::npos) << message;
    }
    // A count left out is taken from the highest number used, and checked alike.
    const std::string highKey = replaced(replaced(test::twillWif(), "[WARP]\nThreads=8\n", "[WARP]\n"),
                                         "[THREADING]\n", "[THREADING]\n1000000000=1\n");
    EXPECT_NE(errorOf(highKey).find("limit of 65536"), std::string::npos);
}

TEST(WifReader, FileLargerThanTheLimitIsRefusedUnread) {
    const test::TempDir dir;
    const std::string path = dir.file("big.wif");
    {
        std::ofstream out(path, std::ios::binary);
        out.seekp(std::streamoff(kMaxWifFileBytes));
        out.put('\n');
    }
    std::vector<std::string> warnings;
    try {
        readWif(path, warnings);
        ADD_FAILURE() << "read a file larger than the limit";
    } catch (const DraftError& e) {
        EXPECT_NE(std::string(e.what()).find("big.wif: larger than woven's limit of 64 MiB"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace woven
