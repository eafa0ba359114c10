#pragma once
// What one repeat of a weave shows from afar: the fraction of the surface each yarn covers (the
// rest is gap), the weights of a far-field average (MODEL.md section 7; the preview's weave
// filter).
#include <glm/glm.hpp>
#include <vector>

#include "weave.h"

namespace woven {

struct WeaveCoverage {
    float weft = 0.0f, warp = 0.0f;  // fractions of the surface
    std::vector<float> yarns;        // the fraction each yarn covers (Weave::yarn() indices)
    // The same split by the cells' top yarn: what the cells with the warp on top hold, and the
    // fraction of the surface those cells are.
    float weftInWarpCells = 0.0f, warpInWarpCells = 0.0f, warpCells = 0.0f;
};

// Over the cells of one repeat of the tile and both sides' thread periods together, at most
// kMaxCoverageSide of them either way (a longer repeat is averaged over its first rows and columns).
constexpr long kMaxCoverageSide = 4096;
WeaveCoverage weaveCoverage(const Weave& weave, bool backSide);

}  // namespace woven
