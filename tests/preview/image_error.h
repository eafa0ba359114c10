#pragma once
// Per-pixel relative error between two linear images over a mask, summarised.
#include <cstdint>
#include <vector>

#include "scene_description.h"

namespace woven::test {

struct ImageError {
    double mean = 0.0, p99 = 0.0;  // of |a - b|_1 / (|b|_1 + floor)
    size_t pixels = 0;
};

// `floor` = 2 % of the reference's mean |b|_1 over the mask, so that dark pixels do not turn
// tiny absolute differences into huge relative ones.
ImageError relativeError(const Image& a, const Image& reference, const std::vector<uint8_t>& mask);

}  // namespace woven::test
