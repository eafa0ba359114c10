#pragma once
// How long one UV unit is on a surface: where a weave's size meets the mesh (a draft's real
// threads per centimetre with "scale": "draft", docs/DRAFTS.md; a material's ends and picks per
// cm, docs/FABRICS.md; the previewer's new cloth).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "material_json.h"
#include "scene_description.h"

namespace woven {

// |dp/du| and |dp/dv| (world units, metres in glTF) over the triangles of scene.meshes[i] for i
// in `meshes`, weighted by their area: the mean, and how far it varies, the root mean square of
// length / mean - 1 (0 where one scale holds everywhere, 0.1 where the UVs stretch by about 10 %).
struct UvScale {
    glm::dvec2 metresPerUv{0.0};
    glm::dvec2 spread{0.0};
};
// Throws std::invalid_argument when none of their triangles has a usable UV mapping.
UvScale measureUvScale(const SceneDescription& scene, const std::vector<size_t>& meshes);
glm::dvec2 worldLengthPerUv(const SceneDescription& scene, const std::vector<size_t>& meshes);  // the mean

// Beyond this spread a real thread count holds only on average: the caller warns
// (unevenUvWarning()). The bundled drapes, whose UVs a cloth simulation stretched, stay under it.
constexpr double kMaxUvSpread = 0.15;
// "the mesh's UVs are uneven (their scale varies by 23 % along u): ..." where the spread is
// beyond kMaxUvSpread, else empty.
std::string unevenUvWarning(const UvScale& scale);

// The `repeat` (threads per UV unit) that puts `threadsPerCm` (along u, v) on those meshes.
glm::vec2 repeatForThreadsPerCm(const glm::dvec2& metresPerUv, const glm::vec2& threadsPerCm);
glm::vec2 repeatForThreadsPerCm(const SceneDescription& scene, const std::vector<size_t>& meshes,
                                const glm::vec2& threadsPerCm);

// `read`'s parameters with its thread counts, where it gives any, made `repeat` on those meshes,
// as scene files, `--woven` and the previewer's panel all take them: the uneven-UV warning goes
// to `warnings` after the key that gave the counts; std::invalid_argument naming that key for a
// repeat out of range (or no UVs to measure).
WovenParams scaledToMeshes(const MaterialJson& read, const SceneDescription& scene, const std::vector<size_t>& meshes,
                           std::vector<std::string>& warnings);

}  // namespace woven
