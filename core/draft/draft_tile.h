#pragma once
// What the woven model takes from a draft (MODEL.md section 6): the weave tile, in the form of
// WovenParams::tile, and each thread's colour, spacing and thickness, lengths in centimeters.
// Column U of the tile is warp end U (from 0), row V is weft pick V, as MODEL.md draws tiles;
// weaving programs that draw end 1 on the right show the mirror image.
#include <cstddef>
#include <string>
#include <vector>

#include "draft.h"
#include "woven_params.h"  // kMaxTileCells: the model's limit

namespace woven {

struct DraftTile {
    std::vector<std::string> rows;  // one per pick, one character per end: '|' warp on top, '-' weft
    // One entry per end (warp...) or per pick (weft...), or empty where the draft does not say.
    std::vector<glm::vec3> warpColors, weftColors;  // linear RGB
    std::vector<float> warpSpacing, weftSpacing;    // centimeters from one thread to the next
    std::vector<float> warpThickness, weftThickness;  // centimeters
};

// Throws DraftError (prefixed by `name`) when the draft has no interlacement or its tile has
// more than kMaxTileCells cells; `draft` must be valid (validate()).
DraftTile draftTile(const Draft& draft, const std::string& name);

}  // namespace woven
