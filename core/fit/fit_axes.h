#pragma once
// The fit's search space as its optimiser sees it (docs/FIT.md, stage 4): each parameter an axis
// x in [0, 1], mapped linearly or in log10 onto its range, and the woven material's parameters
// that the fit searches, in one vector.
#include <cstddef>
#include <vector>

#include "woven_params.h"

namespace woven {

struct Axis {
    double lo, hi;  // the range's ends, or their log10 where `log`
    bool log;
    double value(double x) const;
    double unit(double v) const;  // v's x, held within [0, 1]
    double clamped(double v) const { return value(unit(v)); }  // v held within the axis
};

// The weft and warp colours, rs, ex and ey (the warp's following the weft's: one photo under one
// light cannot tell them apart), both widths and cy, in that order.
const std::vector<Axis>& fullAxes();
constexpr int kColourAxes = 6;              // the first six: the weft's and the warp's colour
constexpr size_t kRsAxis = kColourAxes;     // the shape's axes follow: ex, ey, the widths, cy

// p's parameters on fullAxes(), each in [0, 1].
std::vector<double> encode(const WovenParams& p);
// p with x's parameters: the colours alone where x holds only kColourAxes.
WovenParams decode(const std::vector<double>& x, WovenParams p);

}  // namespace woven
