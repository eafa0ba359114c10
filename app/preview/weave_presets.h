#pragma once
// Named weaves for the previewer's pattern menu and the screenshot tests: the regular (i, j, k)
// family and hand-drawn tiles (rows of '-' weft / '|' warp, as in MODEL.md).
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

}  // namespace woven
