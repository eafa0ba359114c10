#include "mesh_instances.h"

#include <cmath>

#include "coordinate_limits.h"

namespace woven {

MeshBox ownBox(const Mesh& mesh) {
    MeshBox box;
    for (const glm::vec3& p : mesh.positions)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) box.add(p);
    return box;
}

MeshBox worldBox(const Mesh& mesh) {
    const MeshBox own = ownBox(mesh);
    if (!mesh.instances || own.empty()) return own;
    MeshBox world;
    for (const glm::mat4& m : *mesh.instances)
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p(corner & 1 ? own.hi.x : own.lo.x, corner & 2 ? own.hi.y : own.lo.y,
                              corner & 4 ? own.hi.z : own.lo.z);
            world.add(glm::vec3(m * glm::vec4(p, 1.0f)));
        }
    return world;
}

bool invertible(const glm::mat4& placement) {
    const glm::mat3 linear(placement);
    const float axes = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    const float det = glm::determinant(linear);
    return std::abs(det) > 1e-6f * axes && std::isfinite(det);
}

std::string placementProblem(const glm::mat4& placement, const MeshBox& box) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(placement[c][r])) return "its matrix holds a NaN or infinite value";
    if (!invertible(placement))
        return "its scale is zero along an axis (or its axes are parallel): it has no inverse to trace rays through";
    if (box.empty()) return "";
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y, corner & 4 ? box.hi.z : box.lo.z);
        if (const std::string problem = coordinateProblem(glm::vec3(placement * glm::vec4(p, 1.0f))); !problem.empty())
            return "it places the mesh's box at " + problem;
    }
    return "";
}

}  // namespace woven
