#pragma once
// The corners of a hit triangle of the render's meshes, in world space: what a hit's shading
// frame is interpolated from (RenderScene::Impl::makeHit) and what finds the rectangular lamps
// among emissive triangles (emissive_lights.cpp).
#include <glm/glm.hpp>

#include "scene_description.h"

namespace woven {

// A hit triangle's corners in world space: the mesh's own, or an instanced copy's placed by its
// matrix as the loader places a node's mesh (gltf_loader.cpp's addPrimitive: normals by the
// inverse transpose, tangents by the matrix and made perpendicular again, the winding swapped
// under a mirroring matrix), so that a copy shades as the same mesh expanded into the world would.
struct Corners {
    glm::uvec3 tri;  // the vertex indices in the world's winding
    float b1, b2;    // the hit's barycentrics in that winding
    const glm::mat4* placement;  // an instanced copy's matrix, or null
    bool mirrored;               // the placement swaps the winding
    glm::vec3 p[3];
    glm::vec3 n[3];  // where the mesh has normals (hitCorners)
    glm::vec4 t[3];  // where it has tangents (hitCorners)
};

// The corners' positions and winding alone: what finding rectangular lamps needs of them.
Corners cornerPositions(const Mesh& mesh, int instance, unsigned prim, float b1, float b2);

// The positions, normals and tangents.
Corners hitCorners(const Mesh& mesh, int instance, unsigned prim, float b1, float b2);

}  // namespace woven
