#pragma once
// A SceneDescription written as a glTF 2.0 file: `.glb` (the JSON and one binary chunk) or
// `.gltf` (JSON with the buffer and the PNG images embedded as data URIs, so that one file is the
// whole scene either way). What woven reads, written back: the meshes in world space (one node per
// node path the loader kept, so woven's targets name the same parts), their materials with every
// extension woven renders (KHR_texture_transform, KHR_materials_*), a woven material's parameters
// as WOVEN_fabric, the camera and KHR_lights_punctual lights (woven's W/sr and W/m^2 times 683
// lm/W, the loader's rule inverted). The file is written atomically.
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

struct GltfExportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Writes `scene` with `camera` (woven's view of it). A float texture is written as 8 bits, with a
// line in `warnings`. Throws GltfExportError naming the file (an unknown extension, a file that
// cannot be written); no file is left behind then.
void writeGltf(const std::string& path, const SceneDescription& scene, const Camera& camera,
               std::vector<std::string>& warnings);

}  // namespace woven
