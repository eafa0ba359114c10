#pragma once
// The preview's progressive refinement: while nothing changes, successive frames sample each
// pixel at other points of a 3 x 3 grid and the view shows their running mean, so a resting view
// is antialiased as core's pixels are (core's 3 x 3 stratified positions are these points), while
// every frame still costs one sample a pixel. The first frame samples the pixel's centre, as a
// single frame always did.
#include <glm/vec2.hpp>

namespace woven {

constexpr int kRefinementFrames = 9;

// Where frame `index` (0 to kRefinementFrames - 1) samples each pixel, in pixels from its centre.
inline glm::vec2 refinementOffset(int index) {
    // The centre first, then the corners and edges of the grid, alternating sides.
    static constexpr int kOrder[kRefinementFrames][2] = {{0, 0},  {-1, -1}, {1, 1},  {-1, 1}, {1, -1},
                                                         {0, -1}, {0, 1},   {-1, 0}, {1, 0}};
    return glm::vec2(float(kOrder[index][0]), float(kOrder[index][1])) / 3.0f;
}

}  // namespace woven
