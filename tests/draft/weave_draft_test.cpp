// A material's weave and thread colours as a draft (core/draft/weave_draft.h): the draft weaves
// back the same cloth, thread by thread, for the library's fabrics, the (i, j, k) family and a
// drawn tile; weaves a draft cannot hold are refused by name.
#include <gtest/gtest.h>

#include "draft_material.h"
#include "fabric_library.h"
#include "material_json.h"
#include "weave_draft.h"
#include "weave_pattern.h"

namespace woven::test {
namespace {

glm::vec3 colourAt(const std::vector<glm::vec3>& list, const glm::vec3& single, int thread) {
    return list.empty() ? single : list[size_t(thread) % list.size()];
}

// The top yarn and both threads' colours at every crossing over the draft's whole span.
void expectSameCloth(const WovenParams& p, const std::string& name) {
    const Draft draft = weaveDraft(p, name);
    std::vector<std::string> warnings;
    const WovenParams woven = applyDraft(draft, name, p, DraftWidths{}, warnings);
    EXPECT_TRUE(warnings.empty()) << name;
    const WeavePattern before = WeavePattern::fromParams(p), after = WeavePattern::fromParams(woven);
    for (int pick = 0; pick < draft.picks(); ++pick)
        for (int end = 0; end < draft.ends(); ++end) {
            ASSERT_EQ(before.top(end, pick), after.top(end, pick)) << name << " end " << end << " pick " << pick;
            ASSERT_EQ(colourAt(p.warp_colors, p.warp_color, end), colourAt(woven.warp_colors, woven.warp_color, end)) << name;
            ASSERT_EQ(colourAt(p.weft_colors, p.weft_color, pick), colourAt(woven.weft_colors, woven.weft_color, pick)) << name;
        }
}

TEST(WeaveDraft, EveryLibraryFabricWeavesBackThreadByThread) {
    for (const std::string& name : fabricNames()) {
        std::vector<std::string> warnings;
        const MaterialJson m = materialFromJson(nlohmann::json{{"preset", name}}, WovenParams{}, "", warnings);
        expectSameCloth(m.params, name);
    }
}

TEST(WeaveDraft, TheRegularFamilyAndADrawnTileWeaveBack) {
    WovenParams p;
    for (const glm::ivec3 pattern : {glm::ivec3(1, 1, 1), glm::ivec3(1, 3, 1), glm::ivec3(2, 2, 3), glm::ivec3(1, 7, 3)}) {
        p.pattern = pattern;
        expectSameCloth(p, "pattern");
    }
    p.tile = {"||-", "-|-"};
    p.warp_colors = {{1, 0, 0}, {0, 1, 0}};  // a colour sequence of 2 against a weave of 3: 6 ends
    expectSameCloth(p, "tile");
    EXPECT_EQ(weaveDraft(p, "tile").ends(), 6);
}

TEST(WeaveDraft, AWeaveWiderThanADraftsShaftsIsRefusedByName) {
    WovenParams p;
    p.tile = {std::string(300, '|') + "-"};
    try {
        weaveDraft(p, "wide weave");
        FAIL() << "a 301-end weave was drawn on 256 shafts";
    } catch (const DraftError& e) {
        EXPECT_NE(std::string(e.what()).find("wide weave: its weave repeats over 301 ends"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace woven::test
