// A tile of the regular family is told as its (i, j, k) (weave_presets.h's regularWeaveOf()): the
// panel shows the default denim's draft as the 3/1 twill it is.
#include <gtest/gtest.h>

#include "weave_pattern.h"
#include "weave_presets.h"

namespace woven {
namespace {

std::vector<std::string> rows(const WeavePattern& pattern, int columns, int count) {
    std::vector<std::string> out;
    std::string drawing = pattern.draw(columns, count), line;
    for (char c : drawing)
        if (c == '\n') out.push_back(line), line.clear();
        else line += c;
    if (!line.empty()) out.push_back(line);
    return out;
}

TEST(RegularWeaveOf, TellsATileOfTheRegularFamilyFromAnyOrigin) {
    EXPECT_EQ(regularWeaveOf({"-|", "|-"}), glm::ivec3(1, 1, 1));
    EXPECT_EQ(regularWeaveOf({"|-", "-|"}), glm::ivec3(1, 1, 1));
    // assets/drafts/denim.wif's tile: weft on top one element in four, moving one to the right a
    // row, as (1, 3, 3)'s does (U + 3 V = 0 mod 4 where the weft is on top).
    EXPECT_EQ(regularWeaveOf({"|||-", "-|||", "|-||", "||-|"}), glm::ivec3(1, 3, 3));
    // The same twill drawn twice each way, and started on another thread.
    const WeavePattern twill = WeavePattern::regular(1, 3, 3);
    EXPECT_EQ(regularWeaveOf(rows(twill, 8, 8)), glm::ivec3(1, 3, 3));
    EXPECT_EQ(regularWeaveOf({"||-|", "|||-", "-|||", "|-||"}), glm::ivec3(1, 3, 3));
    for (const glm::ivec3& weave : {glm::ivec3(4, 1, 2), glm::ivec3(4, 1, 3), glm::ivec3(2, 2, 1)}) {
        const WeavePattern pattern = WeavePattern::regular(weave.x, weave.y, weave.z);
        EXPECT_EQ(regularWeaveOf(rows(pattern, 2 * pattern.width(), 2 * pattern.height())), weave);
    }
}

TEST(RegularWeaveOf, NoneForTilesOutsideTheFamily) {
    for (const WeavePreset& preset : weavePresets())
        if (!preset.tile.empty()) EXPECT_EQ(regularWeaveOf(preset.tile), std::nullopt) << preset.name;
    EXPECT_EQ(regularWeaveOf({}), std::nullopt);
    EXPECT_EQ(regularWeaveOf({"--", "--"}), std::nullopt);  // weft alone: no weave
}

}  // namespace
}  // namespace woven
