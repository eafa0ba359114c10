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
    };
    std::vector<MapUse> used;
    for (const MapUse& map : all)
        if (*map.ref) used.push_back(map);
    return used;
}

std::string gltfProgramPreamble(const Material& m, bool shadows) {
    std::string defines;
    const std::vector<MapUse> maps = gltfMaps(m);
    for (size_t i = 0; i < maps.size(); ++i) defines += "#define " + std::string(maps[i].define) + " " + std::to_string(i) + "\n";
    defines += "#define MAP_COUNT " + std::to_string(maps.size()) + "\n";
    if (m.alphaMode == AlphaMode::Mask) defines += "#define ALPHA_MASK\n";
    if (m.alphaMode == AlphaMode::Blend) defines += "#define ALPHA_BLEND\n";
    if (m.unlit) defines += "#define UNLIT\n";
    if (shadows) defines += "#define PREVIEW_SHADOWS\n";
    return defines;
}

std::unique_ptr<ShaderProgram> buildGltfProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"frame.glsl", "lighting.glsl", "screen_door.glsl", "gltf_bxdf.glsl", "gltf.frag"},
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
    const std::vector<MapUse> maps = gltfMaps(m);
    for (size_t i = 0; i < maps.size(); ++i) {
        const int unit = firstUnit + int(i);
        textures.bind(*maps[i].ref, unit);
        const std::string index = "[" + std::to_string(i) + "]";
        glUniform1i(program.uniform(("maps" + index).c_str()), unit);
        glUniform1i(program.uniform(("mapTexCoord" + index).c_str()), maps[i].ref->texCoord);
        glUniformMatrix3fv(program.uniform(("mapTransform" + index).c_str()), 1, GL_FALSE,
                           glm::value_ptr(maps[i].ref->uvTransform));
    }
}

}  // namespace woven
