#pragma once
// How much of the sky each vertex sees, for the preview's ambient term: the path tracer's
// environment is occluded by the scene (a fold of cloth, the floor under a hanging drape), the
// preview's constant ambient radiance is not, so the ambient is weighed per vertex by this share.
// Traced once per mesh upload on core's own BVH (RenderScene); plain data, no GL.
#include <glm/glm.hpp>
#include <vector>

#include "scene_description.h"

namespace woven {

class RenderScene;
struct SurfaceHit;

// Per mesh of `scene`, per vertex: the cosine-weighted share of directions about its normal that
// leave the scene unblocked, on the normal's side (x) and on the other (y), from kSkyRays
// stratified directions a side. An instanced mesh's copies each see another sky: (1, 1) there,
// as for a vertex without a normal.
constexpr int kSkyRays = 64;
std::vector<std::vector<glm::vec2>> skyVisibility(const SceneDescription& scene);

// A fingerprint of what skyVisibility() reads (each mesh's positions, normals, triangles and
// instances), so that a material edit, which sends the meshes to the GPU again, traces nothing.
size_t skyVisibilityKey(const SceneDescription& scene);

// Ray i of `count` cosine-weighted directions about +z: a Fibonacci spiral on the disc, lifted to
// the hemisphere, turned by `turn` (of a whole turn; vertexTurn() gives each vertex its own, so
// that neighbours' errors do not line up). bounced_light.h casts its rays the same way.
glm::vec3 spiralDirection(int i, int count, float turn);
float vertexTurn(uint32_t key);
// The share of `count` spiralDirection()s about unit n (turned by `turn`) that leave `scene`
// unblocked from `from`: a vertex's sky here, a bounce's hit's in bounced_light.h.
float openShare(const RenderScene& scene, const SurfaceHit& from, const glm::vec3& n, int count, float turn);

}  // namespace woven
