#pragma once
// The meshes of the drape scene, before they become glTF: plain indexed triangles with
// per-vertex normals and optional UVs.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "cloth_simulation.h"

namespace drape {

struct TriangleMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;  // empty or one per vertex
    std::vector<uint32_t> indices;  // counter-clockwise seen from the front
};

// The simulated cloth: grid UVs over [0, 1]^2 (u along i, v along j), area-weighted smooth
// normals, both triangles of each cell split along the same diagonal.
TriangleMesh clothMesh(const ClothSimulation& cloth);

// A latitude-longitude sphere.
TriangleMesh sphereMesh(const glm::vec3& center, float radius, int segments, int rings);

// A box with rounded edges: a subdivided cube whose vertices are pushed onto the rounded
// surface (each one to its nearest point of the inner box, plus radius along the offset).
TriangleMesh roundedBoxMesh(const glm::vec3& center, const glm::vec3& halfExtent, float radius, int divisions);

// A parallelogram corner + s * edgeU + t * edgeV; its front faces along cross(edgeU, edgeV).
TriangleMesh quadMesh(const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV);

// A square of side `size` centred at `center`, its front facing along `normal`.
TriangleMesh facingSquare(const glm::vec3& center, const glm::vec3& normal, float size);

}  // namespace drape
