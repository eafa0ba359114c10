#pragma once
// A pixel's footprint at a hit, as the weave filter uses it: from how the point moves from one
// pixel to the next (dp/dx, dp/dy: ray differentials, CameraModel::footprint()) to how its uv
// does, through the surface's dp/du and dp/dv (least squares, as pbrt's ComputeDifferentials).
#include "interaction.h"

namespace woven {

// Sets hit.duvdx and hit.duvdy; zero where dp/du and dp/dv do not span the surface.
void setUvFootprint(SurfaceHit& hit, const glm::vec3& dpdx, const glm::vec3& dpdy);

}  // namespace woven
