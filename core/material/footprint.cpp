#include "footprint.h"

#include <algorithm>
#include <cmath>

namespace woven {

void setUvFootprint(SurfaceHit& hit, const glm::vec3& dpdx, const glm::vec3& dpdy) {
    // Solve dp = dp/du du + dp/dv dv in the least-squares sense (the normal equations of the 3 x 2
    // system), in double: dp/du and dp/dv may be far from unit length.
    const glm::dvec3 a(hit.dpdu), b(hit.dpdv);
    const double aa = glm::dot(a, a), ab = glm::dot(a, b), bb = glm::dot(b, b);
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * aa * bb) || !std::isfinite(det)) {
        hit.duvdx = hit.duvdy = glm::vec2(0.0f);
        return;
    }
    auto solve = [&](const glm::vec3& dp) {
        const glm::dvec3 d(dp);
        const double ad = glm::dot(a, d), bd = glm::dot(b, d);
        const glm::dvec2 duv((bb * ad - ab * bd) / det, (aa * bd - ab * ad) / det);
        // A footprint reaching along the surface to the horizon is huge, not infinite.
        return glm::vec2(glm::clamp(duv, glm::dvec2(-1e8), glm::dvec2(1e8)));
    };
    hit.duvdx = solve(dpdx);
    hit.duvdy = solve(dpdy);
}

}  // namespace woven
