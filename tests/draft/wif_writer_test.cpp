// The WIF writer: the sections weaving programs expect, and the round trip (write, read, the
// same draft) on files and on random drafts of every shape.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>

#include "atomic_file.h"
#include "drawdown.h"
#include "image_io.h"
#include "temp_dir.h"
#include "wif_reader.h"
#include "wif_test_files.h"
#include "wif_writer.h"

namespace woven {
namespace {

Draft readBack(const Draft& draft, std::vector<std::string>& warnings) {
    const test::TempDir dir;
    const std::string path = dir.file("written.wif");
    writeWif(path, draft);
    return readWif(path, warnings);
}

TEST(WifWriter, WritesTheSectionsWeavingProgramsExpect) {
    std::vector<std::string> warnings;
    const std::string text = formatWif(test::readText(test::twillWif(), warnings), "twill");
    for (const char* line : {"[WIF]\r\nVersion=1.1\r\nDate=April 20, 1997\r\nDevelopers=wif@mhsoft.com\r\nSource Program=woven\r\n",
                             "[CONTENTS]\r\n", "WEAVING=true\r\n", "TIEUP=true\r\n",
                             "[WEAVING]\r\nShafts=4\r\nTreadles=4\r\nRising Shed=true\r\n",
                             "[WARP]\r\nThreads=8\r\nUnits=Centimeters\r\nColor=1\r\n", "[WEFT]\r\nThreads=8\r\n",
                             "[COLOR PALETTE]\r\nEntries=2\r\nForm=RGB\r\nRange=0,255\r\n",
                             "[COLOR TABLE]\r\n1=255,255,255\r\n2=0,0,0\r\n", "[THREADING]\r\n1=1\r\n2=2\r\n",
                             "[TIEUP]\r\n1=1,2\r\n2=2,3\r\n3=3,4\r\n4=1,4\r\n", "[TREADLING]\r\n1=1\r\n"})
        EXPECT_NE(text.find(line), std::string::npos) << line;
    // Uniform threads need no per-thread sections; a lift plan that is absent is not written.
    for (const char* absent : {"[WARP COLORS]", "[WEFT SPACING]", "[LIFTPLAN]", "[TEXT]", "LIFTPLAN=true"})
        EXPECT_EQ(text.find(absent), std::string::npos) << absent;
}

TEST(WifWriter, ReadWriteReadGivesTheSameDraftAndTheSameText) {
    std::string text = test::replaced(test::twillWif(), "[WARP]\nThreads=8\nColor=1\n",
                                      "[WARP]\nThreads=8\nColor=1\nUnits=Decipoints\nSpacing=100\nThickness=80.5\n");
    text = test::replaced(text, "[WEFT]\nThreads=8\nColor=2\n", "[WEFT]\nThreads=8\nColor=2\nUnits=centimeters\nSpacing=0.1\nThickness=0.05\n");
    text += "[WARP COLORS]\n3=2\n4=2\n[WEFT SPACING]\n2=0.2\n[WEFT THICKNESS]\n1=0.1\n[TEXT]\nTitle=Caf\xE9; 2/2\n";
    text += "[LIFTPLAN]\n1=1,2\n2=2,3\n3=3,4\n4=1,4\n5=1,2\n6=2,3\n7=3,4\n8=1,4\n";
    for (const std::string& source : {text, test::plainLiftplanWif(), test::twillWif()}) {
        std::vector<std::string> warnings;
        const Draft first = test::readText(source, warnings);
        const Draft second = readBack(first, warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        EXPECT_EQ(second, first);
        EXPECT_EQ(formatWif(second, "second"), formatWif(first, "first"));
    }
}

// Random drafts of every shape the Draft allows: 1-40 shafts, 0-12 treadles, threads on
// several shafts or none, tie-up with treadling, a lift plan, or both, either shed, colours
// from an 8-bit palette, lengths in every unit, lists given or not.
class RandomDrafts {
public:
    explicit RandomDrafts(uint32_t seed) : random_(seed) {}

    Draft next() {
        Draft d;
        d.shafts = integer(1, 40);
        d.treadles = integer(0, 12);
        d.risingShed = integer(0, 1);
        d.title = integer(0, 1) ? "Draft " + std::to_string(integer(0, 9999)) + " \xC3\xA9; a=b [x]" : "";
        for (int c = integer(0, 6); c > 0; --c) d.palette.push_back(byteColor());
        d.warp = threads(d.palette);
        d.weft = threads(d.palette);
        d.threading = sets(d.ends(), d.shafts, 3);
        // 0: tie-up and treadling, 1: lift plan, 2: all three, agreeing as weaving programs write them
        const int form = integer(0, 2);
        if (form != 1 && d.treadles > 0) {
            d.tieup = sets(d.treadles, d.shafts, 4);
            d.treadling = sets(d.picks(), d.treadles, 2);
        }
        if (form == 2 && !d.tieup.empty()) {
            for (int pick = 0; pick < d.picks(); ++pick) d.liftplan.push_back(shedOf(d, pick));
        } else if (form != 0 || d.tieup.empty()) {
            d.liftplan = sets(d.picks(), d.shafts, 5);
        }
        return d;
    }

private:
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }

    glm::vec3 byteColor() {
        glm::vec3 c;
        for (int k = 0; k < 3; ++k) c[k] = srgbToLinear(float(integer(0, 255)) / 255.0f);
        return c;
    }

    DraftThreads threads(const std::vector<glm::vec3>& palette) {
        DraftThreads t;
        t.count = integer(1, 70);
        t.units = LengthUnit(integer(0, 2));
        if (!palette.empty() && integer(0, 1))
            for (int i = 0; i < t.count; ++i) t.colors.push_back(palette[size_t(integer(0, int(palette.size()) - 1))]);
        const float spacing = std::uniform_real_distribution<float>(0.01f, 300.0f)(random_);
        if (integer(0, 1)) t.spacing.assign(size_t(t.count), spacing);
        if (integer(0, 1))
            for (int i = 0; i < t.count; ++i) t.thickness.push_back(std::uniform_real_distribution<float>(0.001f, 10.0f)(random_));
        return t;
    }

    // Sets of up to `most` members of 0..members-1 (some empty).
    std::vector<IndexSet> sets(int count, int members, int most) {
        std::vector<IndexSet> out(static_cast<size_t>(count));
        for (IndexSet& s : out)
            for (int n = integer(0, most); n > 0; --n) s.set(size_t(integer(0, members - 1)));
        return out;
    }

    std::mt19937 random_;
};

TEST(WifWriter, RandomDraftsSurviveTheRoundTrip) {
    RandomDrafts drafts(12345);
    for (int i = 0; i < 300; ++i) {
        const Draft draft = drafts.next();
        std::vector<std::string> warnings;
        const Draft back = readBack(draft, warnings);
        EXPECT_EQ(back, draft) << "draft " << i << ":\n" << formatWif(draft, "random");
        EXPECT_TRUE(warnings.empty()) << "draft " << i << ": " << warnings.front();
        if (HasFailure()) break;
    }
}

TEST(WifWriter, ThreadColoursMissingFromThePaletteAreAdded) {
    std::vector<std::string> warnings;
    Draft d = test::readText(test::plainLiftplanWif(), warnings);
    const glm::vec3 red(1.0f, 0.0f, 0.0f), blue(0.0f, 0.0f, 1.0f);
    d.warp.colors = {red, blue, red, blue};
    const Draft back = readBack(d, warnings);
    EXPECT_EQ(back.warp.colors, d.warp.colors);
    EXPECT_EQ(back.palette, (std::vector<glm::vec3>{red, blue}));
}

TEST(WifWriter, AnAllEmptyListStaysPresent) {
    // A lift plan that lifts nothing is still a lift plan: it is written as "1=0".
    std::vector<std::string> warnings;
    Draft d = test::readText(test::plainLiftplanWif(), warnings);
    for (IndexSet& pick : d.liftplan) pick.reset();
    EXPECT_NE(formatWif(d, "empty").find("[LIFTPLAN]\r\n1=0\r\n"), std::string::npos);
    EXPECT_EQ(readBack(d, warnings), d);
}

TEST(WifWriter, RefusesDraftsNoReaderCouldUseAndLeavesNoFile) {
    std::vector<std::string> warnings;
    const Draft good = test::readText(test::twillWif(), warnings);
    Draft beyond = good;
    beyond.threading[2].set(7);  // shaft 8 of 4
    Draft noInterlacement = good;
    noInterlacement.treadling.clear();
    Draft badSize = good;
    badSize.warp.colors.pop_back();
    Draft badColor = good;
    badColor.weft.colors[0].x = 1.5f;
    Draft badSpacing = good;
    badSpacing.warp.spacing.assign(8, 0.0f);
    const test::TempDir dir;
    for (const Draft* bad : {&beyond, &noInterlacement, &badSize, &badColor, &badSpacing}) {
        const std::string path = dir.file("bad.wif");
        EXPECT_THROW(writeWif(path, *bad), DraftError);
        EXPECT_FALSE(std::ifstream(path).good());
        EXPECT_FALSE(std::ifstream(temporaryPathFor(path)).good());
    }
    EXPECT_THROW(writeWif(dir.file("no/such/folder/draft.wif"), good), FileWriteError);
}

}  // namespace
}  // namespace woven
