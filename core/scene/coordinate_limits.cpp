#include "coordinate_limits.h"

#include <cmath>
#include <sstream>

namespace woven {

std::string coordinateProblem(const glm::vec3& p) {
    // A NaN fails these comparisons too. Every vertex is checked: the message is built only when needed.
    if (std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.z) <= kMaxCoordinate) return "";
    std::ostringstream s;
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(p[c])) return s.str() + " is not finite";
    s << " lies beyond woven's limit of " << kMaxCoordinate
      << " m from the origin on an axis (rays and light powers overflow far out; docs/LIMITS.md)";
    return s.str();
}

}  // namespace woven
