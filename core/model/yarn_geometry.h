#pragma once
// Where a UV point lands in the weave (MODEL.md sections 2 and 6): which thread is seen there,
// the coordinates along and across it, and its bumped normal from its yarn's c_y cross-section
// and the crimp.
#include <glm/glm.hpp>

#include "weave.h"

namespace woven {

struct YarnPoint {
    YarnType type = YarnType::Gap;
    int64_t yarnIndex = 0;  // row V for weft, column U for warp: seeds the per-yarn noise
    int slot = 0;           // the thread's slot in its side's ThreadLayout: its colour
    int yarn = 0;           // its yarn: Weave::yarn(yarn)
    double along = 0.0;     // position along the yarn in element units (continuous on one yarn)
    // Bumped normal in the tangent frame (x = +u, y = +v, z = surface normal); unit length.
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

// `weave` is built from `p`; `backSide`: the back face is looked at, where the other yarn is on top.
YarnPoint yarnAt(const Weave& weave, const WovenParams& p, bool backSide, glm::dvec2 uv);

// The cross-section normal (across, up) for x in [-1, 1], in MODEL.md's finite form.
glm::vec2 crossSectionNormal(float cy, float x);
// The bumped normal in the tangent frame of a yarn along axis `alongAxis` (0 = u, 1 = v) at across
// position x, tilted along the yarn by the crimp slope.
glm::vec3 yarnNormal(int alongAxis, float cy, float x, float slope);

}  // namespace woven
