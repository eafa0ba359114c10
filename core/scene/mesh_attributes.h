#pragma once
// Per-vertex attributes derived from the triangles when a file lacks them, and the clean-up
// every loaded mesh gets. All work on a world-space woven::Mesh.
#include <cstddef>

#include "scene_description.h"

namespace woven {

// Drops triangles with a repeated index or zero (or non-finite) area; returns how many.
size_t removeDegenerateTriangles(Mesh& mesh);

// Drops every triangle whose corners, in any rotation of their order, are those of an earlier
// one (a reflected order is the other face, and stays); returns how many. Coincident copies
// render as one but cost each ray through them a test of every copy, which no BVH avoids.
size_t removeDuplicateTriangles(Mesh& mesh);

// Fills mesh.normals with area-weighted averages of the face normals (counter-clockwise front).
// A vertex no triangle uses gets +z.
void computeVertexNormals(Mesh& mesh);

// Fills mesh.tangents from texture coordinate set `uvSet` (0: uvs, 1: uvs1), as MikkTSpace
// does in what matters for normal maps: dp/du per triangle, accumulated per vertex, made
// orthogonal to the normal; w = +1 when (n x t) points along dp/dv, -1 when against it. A vertex
// shared by triangles of opposite UV orientation (a mirrored half of a model) is split in two,
// so neither side's tangents cancel the other's. Where the UV mapping is degenerate (dp/du = 0)
// any unit vector orthogonal to the normal is used. Requires normals and that uv set.
void computeTangents(Mesh& mesh, int uvSet = 0);

}  // namespace woven
