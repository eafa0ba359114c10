#pragma once
// How long one UV unit is on a surface: where a weave's size meets the mesh (a draft's real
// threads per centimetre with "scale": "draft", docs/DRAFTS.md; the previewer's new cloth).
#include <glm/glm.hpp>
#include <vector>

#include "scene_description.h"

namespace woven {

// The mean |dp/du| and |dp/dv| (world units, metres in glTF) over the triangles of
// scene.meshes[i] for i in `meshes`, weighted by their area. Throws std::invalid_argument when
// none of their triangles has a usable UV mapping.
glm::dvec2 worldLengthPerUv(const SceneDescription& scene, const std::vector<size_t>& meshes);

// The `repeat` (threads per UV unit) that puts `threadsPerCm` (along u, v) on those meshes.
glm::vec2 repeatForThreadsPerCm(const SceneDescription& scene, const std::vector<size_t>& meshes,
                                const glm::vec2& threadsPerCm);

}  // namespace woven
