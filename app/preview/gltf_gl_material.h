#pragma once
// A glTF material on the GPU (shaders/gltf.frag, the twin of core's GltfMaterial): the textures
// it uses as MAP_<NAME> defines in maps[] order, and the upload of every factor and texture.
#include <memory>
#include <string>
#include <vector>

#include "gpu_textures.h"
#include "shader_program.h"
#include "shadow_lookups.h"

namespace woven {

// One factor of gltf.frag: its name, its number of float components (1 to 4) and the value core's
// Material gives it. gltf.frag's declarations are generated from this table (gltfUniformsGlsl(),
// in the preamble) and the upload iterates it, so each factor is named once, as the woven
// parameters are (wovenParamTable()).
struct GltfUniform {
    const char* name;
    int components;
    glm::vec4 (*value)(const Material&);
};
const std::vector<GltfUniform>& gltfUniformTable();
// "uniform vec4 baseColorFactor;\n...": the declarations of the table's uniforms.
std::string gltfUniformsGlsl();

// The textures the material uses, in maps[] order.
std::vector<MapUse> gltfMaps(const Material& material);

// ALPHA_MASK or ALPHA_BLEND as the material's alphaMode says (nothing when opaque).
std::string alphaDefines(const Material& material);

// MAP_<NAME> (index into maps[]), MAP_COUNT, ALPHA_MASK or ALPHA_BLEND, UNLIT, DIFFUSE_TRANSMISSION
// (a diffuse transmission factor above 0), `shadows`' lookups and the factors' declarations.
std::string gltfProgramPreamble(const Material& material, ShadowLookups shadows);
// shaders/mesh.vert + the gltf.frag chain, compiled with `preamble`.
std::unique_ptr<ShaderProgram> buildGltfProgram(const std::string& preamble);
// The transmittance pass's program for a material with diffuse transmission (gltf_shadow.frag),
// from gltfProgramPreamble(material, ShadowLookups::None).
std::unique_ptr<ShaderProgram> buildGltfShadowProgram(const std::string& preamble);

// Sets every factor and binds each map to a texture unit from `firstUnit` on.
void uploadGltfMaterial(const ShaderProgram& program, const Material& material, GpuTextures& textures, int firstUnit);

}  // namespace woven
