#include "weave_presets.h"

#include "weave_pattern.h"

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

namespace {

// Whether the drawn tile is whole tiles of `regular` from some origin.
bool tilesOf(const WeavePattern& drawn, const WeavePattern& regular) {
    if (drawn.width() % regular.width() != 0 || drawn.height() % regular.height() != 0) return false;
    for (int su = 0; su < regular.width(); ++su)
        for (int sv = 0; sv < regular.height(); ++sv) {
            bool same = true;
            for (int v = 0; v < drawn.height() && same; ++v)
                for (int u = 0; u < drawn.width() && same; ++u) same = drawn.topInTile(u, v) == regular.top(u + su, v + sv);
            if (same) return true;
        }
    return false;
}

}  // namespace

std::optional<glm::ivec3> regularWeaveOf(const std::vector<std::string>& tile) {
    if (tile.empty() || tile.size() > size_t(kRegularWeaveMaxPeriod) || tile[0].size() > size_t(kRegularWeaveMaxPeriod))
        return std::nullopt;
    const WeavePattern drawn = WeavePattern::fromRows(tile);
    int weft = 0;
    for (int v = 0; v < drawn.height(); ++v)
        for (int u = 0; u < drawn.width(); ++u) weft += drawn.topInTile(u, v) == YarnType::Weft;
    const int cells = drawn.width() * drawn.height();
    for (int period = 2; period <= drawn.width(); ++period) {
        if (drawn.width() % period != 0) continue;
        // Weft on top in i of each period's elements: the count tells i.
        if (weft * period % cells != 0) continue;
        const int i = weft * period / cells;
        if (i < 1 || i >= period) continue;
        for (int k = 1; k < period; ++k)
            if (tilesOf(drawn, WeavePattern::regular(i, period - i, k))) return glm::ivec3(i, period - i, k);
    }
    return std::nullopt;
}

}  // namespace woven
