#include "mesh_instances.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string_view>
#include <utility>

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

namespace {

// Where an instance places four corners of the box (the lowest and its three neighbours, which
// fix an affine placement), each coordinate as its cell on a grid of a power of two at most
// kCoincidentFraction of the placed box's diagonal.
using PlacementKey = std::array<double, 12>;

PlacementKey placementKey(const glm::mat4& placement, const MeshBox& box) {
    const glm::dmat4 m(placement);
    const glm::dvec3 lo(box.lo), hi(box.hi);
    const glm::dvec3 corners[4] = {lo, {hi.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}};
    glm::dvec3 placed[4];
    for (int c = 0; c < 4; ++c) placed[c] = glm::dvec3(m * glm::dvec4(corners[c], 1.0));
    const double diagonal = glm::length(placed[1] + placed[2] + placed[3] - 3.0 * placed[0]);
    const double cell = diagonal > 0.0 ? std::exp2(std::floor(std::log2(kCoincidentFraction * diagonal))) : 0.0;
    PlacementKey key;
    for (int c = 0; c < 4; ++c)
        for (int a = 0; a < 3; ++a)  // + 0.0: -0 and 0 are one cell
            key[size_t(3 * c + a)] = (cell > 0.0 ? std::floor(placed[c][a] / cell) : placed[c][a]) + 0.0;
    return key;
}

}  // namespace

size_t dropCopies(std::vector<glm::mat4>& placements, const MeshBox& ownBox) {
    MeshBox box = ownBox;
    const bool finite = std::isfinite(box.lo.x + box.lo.y + box.lo.z + box.hi.x + box.hi.y + box.hi.z);
    if (box.empty() || !finite) box.lo = glm::vec3(0.0f), box.hi = glm::vec3(1.0f);
    // Sorted by the hash of each key, then by index: equal keys meet in a run, the first kept.
    std::vector<std::pair<size_t, uint32_t>> order(placements.size());
    for (uint32_t i = 0; i < placements.size(); ++i) {
        const PlacementKey key = placementKey(placements[i], box);
        order[i] = {std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(key.data()), sizeof key)), i};
    }
    std::sort(order.begin(), order.end());
    std::vector<bool> copy(placements.size(), false);
    for (size_t run = 0; run < order.size();) {
        size_t end = run;
        while (end < order.size() && order[end].first == order[run].first) ++end;
        std::vector<PlacementKey> kept;  // the run's distinct keys (one, but for a hash collision)
        for (size_t i = run; i < end; ++i) {
            const PlacementKey key = placementKey(placements[order[i].second], box);
            copy[order[i].second] = std::find(kept.begin(), kept.end(), key) != kept.end();
            if (!copy[order[i].second]) kept.push_back(key);
        }
        run = end;
    }
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
