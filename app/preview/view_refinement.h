#pragma once
// The preview's progressive refinement: while nothing changes, successive frames sample each
// pixel at other points of a 3 x 3 grid and the view shows their running mean, so a resting view
// is antialiased as core's pixels are, while every frame still costs one sample a pixel. The
// points are the 3 x 3 grid sheared by a ninth of a pixel (Chiu, Shirley and Wang's multi-jittered
// arrangement, unjittered): one in each third of the pixel, and each at its own ninth along x and
// along y, so an edge along a row or a column of pixels (a weft's edge seen square on) lands at
// ninths of a pixel, not at thirds. The first frame samples the pixel's centre, as a single frame
// always did.
#include <glm/vec2.hpp>

namespace woven {

constexpr int kRefinementFrames = 9;

// Where frame `index` (0 to kRefinementFrames - 1) samples each pixel, in pixels from its centre.
inline glm::vec2 refinementOffset(int index) {
    // The centre first, then the corners and edges of the grid, alternating sides; point (i, j)
    // of the grid sits at (i / 3 + j / 9, j / 3 + i / 9).
    static constexpr int kOrder[kRefinementFrames][2] = {{0, 0},  {-1, -1}, {1, 1},  {-1, 1}, {1, -1},
                                                         {0, -1}, {0, 1},   {-1, 0}, {1, 0}};
    const glm::vec2 cell{float(kOrder[index][0]), float(kOrder[index][1])};
    return cell / 3.0f + glm::vec2(cell.y, cell.x) / 9.0f;
}

// The side of the box, in pixels, that frame `index`'s sample stands for in the weave filter's
// far field (woven.frag's footprintBox): the whole pixel for the first frame, which a moving view
// shows alone, a third for the others, each its cell of the grid. Whole pixels around every point
// would blur the resting view by a further pixel: a houndstooth's dark blocks at 3 pixels a thread
// came out a third too bright.
inline float refinementFootprint(int index) { return index == 0 ? 1.0f : 1.0f / 3.0f; }

}  // namespace woven
