#pragma once
// Where a UV point lands in the weave (MODEL.md section 2): which yarn is seen there, the
// coordinates along and across it, and its bumped normal from the c_y cross-section and crimp.
#include <glm/glm.hpp>

#include "weave_pattern.h"

namespace woven {

struct YarnPoint {
    YarnType type = YarnType::Gap;
    int64_t yarnIndex = 0;  // row V for weft, column U for warp: seeds the per-yarn noise
    double along = 0.0;     // position along the yarn in element units (continuous on one yarn)
    // Bumped normal in the tangent frame (x = +u, y = +v, z = surface normal); unit length.
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

// `pattern` is the tile of the side being looked at (WeavePattern::reversed() for the back).
YarnPoint yarnAt(const WeavePattern& pattern, const WovenParams& p, glm::dvec2 uv);

// The cross-section normal (across, up) for x in [-1, 1], in MODEL.md's finite form.
glm::vec2 crossSectionNormal(float cy, float x);

}  // namespace woven
