#pragma once
// How long one UV unit is on a material's surface, where a draft's real threads per centimetre
// meet the mesh ("scale": "draft", docs/DRAFTS.md).
#include <glm/glm.hpp>

#include "scene_description.h"

namespace woven {

// The mean |dp/du| and |dp/dv| (world units, metres in glTF) over the triangles of the meshes
// with material `material`, weighted by their area. Throws std::invalid_argument naming the
// material when none of its triangles has a usable UV mapping.
glm::dvec2 worldLengthPerUv(const SceneDescription& scene, int material);

// The `repeat` (threads per UV unit) that puts `threadsPerCm` (along u, v) on that surface.
glm::vec2 repeatForThreadsPerCm(const SceneDescription& scene, int material, const glm::vec2& threadsPerCm);

}  // namespace woven
