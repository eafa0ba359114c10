#pragma once
// The copies of an instanced mesh (EXT_mesh_gpu_instancing, Mesh::instances): how far they may
// go, and what every consumer of a SceneDescription needs to place a mesh in the world without
// expanding it.
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

// Instances a file may hold, over all its nodes. Each costs its 64-byte matrix in the scene and
// an Embree instance (about 400 bytes with its share of the BVH, bench/render/bench_instancing),
// so the limit bounds them near 2 GiB: far beyond the forests and shop shelves the extension is
// made for.
constexpr size_t kMaxInstances = size_t(1) << 22;

struct MeshBox {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool empty() const { return !(lo.x <= hi.x); }
};

// How many times the mesh is drawn: its instances, or once.
inline size_t copies(const Mesh& mesh) { return mesh.instances ? mesh.instances->size() : 1; }

// The box around the mesh's finite positions, in its own space.
MeshBox ownBox(const Mesh& mesh);
// The box around the mesh in the world: its finite positions, or the corners of their box placed
// by each instance (which bounds the copies, rotated ones loosely, for the cost of 8 points a copy).
MeshBox worldBox(const Mesh& mesh);

// Whether a finite matrix has an inverse to trace rays through: no zero scale, no flattened axis
// (relative to the axes' lengths, so that a tiny but sound scale, millimetre parts, passes).
bool invertible(const glm::mat4& placement);

// Copies closer than this fraction of their size (the diagonal of the mesh's box as placed) are
// one copy: a float position holds about 2^-24 of itself, so copies this close differ by a few
// rounding steps (a matrix composed again, a quaternion normalised another way), and a frame of
// 32768 pixels across the copy has pixels 32 times as wide.
constexpr double kCoincidentFraction = 1.0 / (1 << 20);

// Drops the instances that place the mesh's box (`box`; the unit box when empty or unbounded) where
// an earlier one does, within kCoincidentFraction of the copy's size, and returns how many: a copy
// draws the same triangles in the same place, and every ray through a pile of them tests each one
// (a million coincident copies hung a 32 x 24 render), as coincident triangles are dropped within
// a primitive. Positions are compared on a grid of that spacing, so a pile of copies that straddles
// a grid line keeps one copy on each side.
size_t dropCopies(std::vector<glm::mat4>& placements, const MeshBox& box);

// What is wrong with an instance's matrix, or empty: it must be finite and invertible (Embree
// intersects in the mesh's space through its inverse), and place the mesh's own box (`box`)
// within coordinate_limits.h's bound.
std::string placementProblem(const glm::mat4& placement, const MeshBox& box);

}  // namespace woven
