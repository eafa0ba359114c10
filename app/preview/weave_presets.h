#pragma once
// Named weaves for the previewer's pattern menu and the screenshot tests: the regular (i, j, k)
// family and hand-drawn tiles (rows of '-' weft / '|' warp, as in MODEL.md).
#include <optional>
#include <string>
#include <vector>

#include "woven_params.h"

namespace woven {

struct WeavePreset {
    std::string name;
    glm::ivec3 pattern{1, 1, 1};
    std::vector<std::string> tile;  // empty: the (i, j, k) pattern
};

const std::vector<WeavePreset>& weavePresets();  // plain, twill, satin, basket, herringbone, ...

// Sets the weave of `p` (pattern and tile) to the preset's; every other parameter stays.
void applyPreset(const WeavePreset& preset, WovenParams& p);

// The preset whose weave `p` has (its index in weavePresets()), or -1.
int presetOf(const WovenParams& p);

// The (i, j, k) of the regular family (MODEL.md) of which `tile` is whole tiles from some origin
// (a draft's 3/1 twill is (1, 3, 1) whichever thread it starts on), the smallest i + j, then k;
// nullopt where none is: a basket, a herringbone, a tile larger than kRegularWeaveMaxPeriod.
constexpr int kRegularWeaveMaxPeriod = 16;
std::optional<glm::ivec3> regularWeaveOf(const std::vector<std::string>& tile);

}  // namespace woven
