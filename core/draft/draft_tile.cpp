#include "draft_tile.h"

#include "drawdown.h"

namespace woven {

namespace {

std::vector<float> inCentimeters(const std::vector<float>& lengths, LengthUnit unit) {
    std::vector<float> cm;
    cm.reserve(lengths.size());
    for (float length : lengths) cm.push_back(float(toCentimeters(length, unit)));
    return cm;
}

}  // namespace

DraftTile draftTile(const Draft& draft, const std::string& name) {
    if (size_t(draft.ends()) * size_t(draft.picks()) > kMaxTileCells)
        throw DraftError(name + ": the draft's tile of " + std::to_string(draft.ends()) + " x " +
                         std::to_string(draft.picks()) + " threads has more than woven's limit of " +
                         std::to_string(kMaxTileCells) + " cells");
    const Drawdown drawdown(draft, name);
    DraftTile tile;
    tile.rows.assign(size_t(draft.picks()), std::string(size_t(draft.ends()), '-'));
    for (int pick = 0; pick < draft.picks(); ++pick)
        for (int end = 0; end < draft.ends(); ++end)
            if (drawdown.warpOnTop(end, pick)) tile.rows[size_t(pick)][size_t(end)] = '|';
    tile.warpColors = draft.warp.colors;
    tile.weftColors = draft.weft.colors;
    tile.warpSpacing = inCentimeters(draft.warp.spacing, draft.warp.units);
    tile.weftSpacing = inCentimeters(draft.weft.spacing, draft.weft.units);
    tile.warpThickness = inCentimeters(draft.warp.thickness, draft.warp.units);
    tile.weftThickness = inCentimeters(draft.weft.thickness, draft.weft.units);
    return tile;
}

}  // namespace woven
