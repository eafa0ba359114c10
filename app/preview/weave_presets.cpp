#include "weave_presets.h"

namespace woven {

const std::vector<WeavePreset>& weavePresets() {
    static const std::vector<WeavePreset> presets = {
        {"plain (1,1,1)", {1, 1, 1}, {}},
        {"twill (1,2,1)", {1, 2, 1}, {}},
        {"twill 2/2 (2,2,1)", {2, 2, 1}, {}},
        {"satin (9,1,3)", {9, 1, 3}, {}},
        {"sateen (1,4,2)", {1, 4, 2}, {}},
        {"basket 2x2", {1, 1, 1}, {"--||", "--||", "||--", "||--"}},
        // A 2/2 twill whose diagonal turns back every four columns.
        {"herringbone", {1, 1, 1}, {"--||||--", "-||--||-", "||----||", "|--||--|"}},
    };
    return presets;
}

void applyPreset(const WeavePreset& preset, WovenParams& p) {
    p.pattern = preset.pattern;
    p.tile = preset.tile;
}

int presetOf(const WovenParams& p) {
    const auto& presets = weavePresets();
    for (size_t i = 0; i < presets.size(); ++i)
        if (presets[i].tile == p.tile && (!p.tile.empty() || presets[i].pattern == p.pattern)) return int(i);
    return -1;
}

}  // namespace woven
