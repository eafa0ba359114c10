#pragma once
// A U3M (.u3ma archive or .u3m file, U3M 1.1) read as a material for any mesh: a scene file's
// material "u3m": "FABRIC.u3ma" and `--woven TARGET=FABRIC.u3ma` (docs/SCENE_FORMAT.md).
//   woven's own (a custom.woven section, u3m_export.h): the woven parameters it holds, at its
//     thread counts, which the caller layers as it layers any woven material's JSON;
//   anyone else's: its front as a glTF-like textured material (base colour with alpha, normal
//     map, roughness and metalness, IOR, anisotropy's constants), the textures spanning the
//     width and height in mm the file gives them, so that on a mesh the cloth has its real size.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

struct U3mMaterial {
    std::optional<nlohmann::json> woven;  // custom.woven's material, when the file is woven's
    // Otherwise: the material, its textures at textures[0...], each spanning `sizeMm`.
    Material material;
    std::vector<TextureImage> textures;
    glm::dvec2 sizeMm{0.0};
    std::vector<std::string> warnings;  // what the material leaves out of the file's front
};

// Throws std::invalid_argument naming the file and the key: no such file, not a U3M, a path
// that leaves its folder, an image that cannot be decoded.
U3mMaterial readU3m(const std::string& path);

// The foreign material placed on meshes whose texture coordinates are `metresPerUv` long: its
// textures' transforms scaled so each spans sizeMm on the surface.
Material atRealSize(const U3mMaterial& u3m, const glm::dvec2& metresPerUv, int firstTexture);

}  // namespace woven
