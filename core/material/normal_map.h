#pragma once
// glTF's tangent-space normal map at a hit: the shading normal of GltfMaterial, and of a glTF
// material made woven, whose weave WovenSurfaceMaterial bumps on top of it.
#include <optional>

#include "frame.h"
#include "interaction.h"
#include "texture_sampler.h"

namespace woven {

// (tangent, bitangent, normal) of the file's normal at a hit (before ns was turned to ng's
// side: the tangents' handedness is defined against it), unit length; nullopt where the
// tangents are degenerate.
std::optional<Frame> tangentSpace(const SurfaceHit& hit);

// `map` (a normal texture with its scale) applied to the hit's interpolated normal, on the side
// of hit.ns; hit.ns where the tangents or the perturbed normal are degenerate.
glm::vec3 normalMapped(const TextureSampler& map, const SurfaceHit& hit);

}  // namespace woven
