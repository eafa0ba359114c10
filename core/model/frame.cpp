#include "frame.h"

#include <cmath>

namespace woven {

Frame Frame::fromNormal(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    Frame f;
    f.z = n;
    f.x = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.y = glm::vec3(b, sign + n.y * n.y * a, -n.y);
    return f;
}

Frame Frame::fromNormalAndAxis(const glm::vec3& n, const glm::vec3& axis) {
    const glm::vec3 t = axis - glm::dot(axis, n) * n;
    const float len2 = glm::dot(t, t);
    if (!(len2 > 1e-20f) || !std::isfinite(len2)) return fromNormal(n);
    Frame f;
    f.z = n;
    f.x = t * (1.0f / std::sqrt(len2));  // one division, not one per component
    f.y = glm::cross(f.z, f.x);
    return f;
}

}  // namespace woven
