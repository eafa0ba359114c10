#include "mesh_instances.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

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
    // In double: a scale of 1e30 has a determinant of 1e90, past a float, and is no zero scale.
    const glm::dmat3 linear{glm::mat3(placement)};
    const double axes = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    const double det = glm::determinant(linear);
    return std::abs(det) > 1e-6 * axes && std::isfinite(det);
}

size_t dropCopies(std::vector<glm::mat4>& placements) {
    const auto bytes = [&](uint32_t i) { return reinterpret_cast<const char*>(&placements[i]); };
    std::vector<uint32_t> order(placements.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return std::memcmp(bytes(a), bytes(b), sizeof(glm::mat4)) < 0; });
    std::vector<bool> copy(placements.size(), false);
    for (size_t i = 1; i < order.size(); ++i)
        copy[order[i]] = std::memcmp(bytes(order[i]), bytes(order[i - 1]), sizeof(glm::mat4)) == 0;
    size_t kept = 0;
    for (size_t i = 0; i < placements.size(); ++i)
        if (!copy[i]) placements[kept++] = placements[i];
    const size_t dropped = placements.size() - kept;
    placements.resize(kept);
    return dropped;
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
