#pragma once
// An orthonormal basis: x = the lobe's anisotropy axis (along the yarn), z = the shading normal.
#include <glm/glm.hpp>

namespace woven {

struct Frame {
    glm::vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};

    glm::vec3 toLocal(const glm::vec3& v) const { return {glm::dot(v, x), glm::dot(v, y), glm::dot(v, z)}; }
    glm::vec3 toWorld(const glm::vec3& v) const { return v.x * x + v.y * y + v.z * z; }

    // Any frame around a unit normal (Duff et al. 2017, branchless).
    static Frame fromNormal(const glm::vec3& n);
    // z = n, x = `axis` projected into the plane of n; falls back to fromNormal(n) when the
    // projection vanishes or is not finite.
    static Frame fromNormalAndAxis(const glm::vec3& n, const glm::vec3& axis);
};

}  // namespace woven
