#include "gltf_gl_material.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

namespace woven {

std::vector<MapUse> gltfMaps(const Material& m) {
    const MapUse all[] = {
        {"MAP_BASE_COLOR", &m.baseColorTexture},
        {"MAP_METALLIC_ROUGHNESS", &m.metallicRoughnessTexture},
        {"MAP_NORMAL", &m.normalTexture},
        {"MAP_OCCLUSION", &m.occlusionTexture},
        {"MAP_EMISSIVE", &m.emissiveTexture},
        {"MAP_SPECULAR", &m.specularTexture},
        {"MAP_SPECULAR_COLOR", &m.specularColorTexture},
        {"MAP_SHEEN_COLOR", &m.sheen.colorTexture},
        {"MAP_SHEEN_ROUGHNESS", &m.sheen.roughnessTexture},
        {"MAP_CLEARCOAT", &m.clearcoat.texture},
        {"MAP_CLEARCOAT_ROUGHNESS", &m.clearcoat.roughnessTexture},
        {"MAP_TRANSMISSION", &m.transmission.texture},
        {"MAP_ANISOTROPY", &m.anisotropy.texture},
        {"MAP_IRIDESCENCE", &m.iridescence.texture},
        {"MAP_IRIDESCENCE_THICKNESS", &m.iridescence.thicknessTexture},
    };
    std::vector<MapUse> used;
    for (const MapUse& map : all)
        if (*map.ref) used.push_back(map);
    return used;
}

std::string alphaDefines(const Material& m) {
    switch (m.alphaMode) {
        case AlphaMode::Mask: return "#define ALPHA_MASK\n";
        case AlphaMode::Blend: return "#define ALPHA_BLEND\n";
        case AlphaMode::Opaque: break;
    }
    return "";
}

std::string gltfProgramPreamble(const Material& m, bool shadows) {
    std::string defines = mapDefines(gltfMaps(m)) + alphaDefines(m);
    if (m.unlit) defines += "#define UNLIT\n";
    if (shadows) defines += "#define PREVIEW_SHADOWS\n";
    return defines;
}

std::unique_ptr<ShaderProgram> buildGltfProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"mesh_varyings.glsl", "frame.glsl", "lighting.glsl", "screen_door.glsl", "texture_maps.glsl",
                                 "normal_map.glsl", "gltf_iridescence.glsl", "gltf_bxdf.glsl", "gltf.frag"},
        preamble);
}

void uploadGltfMaterial(const ShaderProgram& program, const Material& m, GpuTextures& textures, int firstUnit) {
    glUniform4fv(program.uniform("baseColorFactor"), 1, glm::value_ptr(m.baseColor));
    glUniform1f(program.uniform("metallicFactor"), m.metallic);
    glUniform1f(program.uniform("roughnessFactor"), m.roughness);
    glUniform1f(program.uniform("normalScale"), m.normalTexture.scale);
    glUniform1f(program.uniform("occlusionStrength"), m.occlusionTexture.scale);
    glUniform1f(program.uniform("alphaCutoff"), m.alphaCutoff);
    const float r = (m.ior - 1.0f) / (m.ior + 1.0f);
    glUniform1f(program.uniform("iorF0"), m.ior == 0.0f ? 1.0f : r * r);
    glUniform1f(program.uniform("specularFactor"), m.specular);
    glUniform3fv(program.uniform("specularColorFactor"), 1, glm::value_ptr(m.specularColor));
    glUniform3fv(program.uniform("sheenColorFactor"), 1, glm::value_ptr(m.sheen.color));
    glUniform1f(program.uniform("sheenRoughnessFactor"), m.sheen.roughness);
    glUniform1f(program.uniform("anisotropyStrength"), m.anisotropy.strength);
    glUniform2f(program.uniform("anisotropyRotation"), std::cos(m.anisotropy.rotation), std::sin(m.anisotropy.rotation));
    glUniform1f(program.uniform("clearcoatFactor"), m.clearcoat.factor);
    glUniform1f(program.uniform("clearcoatRoughnessFactor"), m.clearcoat.roughness);
    glUniform1f(program.uniform("transmissionFactor"), m.transmission.factor);
    glUniform1f(program.uniform("iridescenceFactor"), m.iridescence.factor);
    glUniform1f(program.uniform("iridescenceIor"), m.iridescence.ior);
    glUniform2f(program.uniform("iridescenceThickness"), m.iridescence.thicknessMin, m.iridescence.thicknessMax);
    textures.bindMaps(program, gltfMaps(m), firstUnit);
}

}  // namespace woven
