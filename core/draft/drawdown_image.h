#pragma once
// A drawdown in thread colours, as weaving programs draw one: each cell of the weave takes the
// colour of the yarn on top there. Laid out like WeavePattern::draw (column U left to right,
// row V top to bottom), one square of cellPixels per cell.
#include <cstddef>
#include <vector>

#include "image.h"
#include "weave_pattern.h"

namespace woven {

constexpr size_t kMaxDrawdownPixels = size_t(1) << 24;

// warpColors[U mod size] colours end U, weftColors[V mod size] pick V (linear RGB; neither
// empty). Throws std::invalid_argument for a non-positive size, empty colour lists, or an
// image of more than kMaxDrawdownPixels pixels.
Image drawdownImage(const WeavePattern& weave, const std::vector<glm::vec3>& warpColors,
                    const std::vector<glm::vec3>& weftColors, int columns, int rows, int cellPixels);

}  // namespace woven
