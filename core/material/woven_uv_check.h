#pragma once
// What the UVs of the meshes a woven material covers let the weave show, checked when
// SceneMaterials builds the material (once per render), each finding one warning line on stderr:
// - UVs so large that a float cannot place a point within a quarter of a thread
//   (uv_precision.h): shaded there by the weave's far field. One line for the material, with the
//   largest |uv| and its mesh.
// - a mesh whose UVs are all equal: they map no weave (dp/du is undefined), so it is shaded as
//   solid cloth, as a mesh without UVs. One line naming the mesh. (All equal at a uv a float
//   cannot resolve, as 1e10 plus a few units reads, is the first case.)
#include <vector>

#include "scene_description.h"

namespace woven {

// Whether the mesh has UVs and they are all one point.
bool uvsAllEqual(const Mesh& mesh);

// Checks the meshes of scene.materials[material], which must be woven; returns, per mesh of the
// scene, whether it is one of them to shade as solid cloth.
std::vector<bool> checkWovenUvs(const SceneDescription& scene, int material);

}  // namespace woven
