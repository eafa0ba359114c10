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
        {"MAP_DIFFUSE_TRANSMISSION", &m.diffuseTransmission.texture},
        {"MAP_DIFFUSE_TRANSMISSION_COLOR", &m.diffuseTransmission.colorTexture},
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

const std::vector<GltfUniform>& gltfUniformTable() {
    using M = const Material&;
    static const std::vector<GltfUniform> table = {
        {"baseColorFactor", 4, [](M m) { return m.baseColor; }},
        {"metallicFactor", 1, [](M m) { return glm::vec4(m.metallic); }},
        {"roughnessFactor", 1, [](M m) { return glm::vec4(m.roughness); }},
        {"normalScale", 1, [](M m) { return glm::vec4(m.normalTexture.scale); }},
        {"occlusionStrength", 1, [](M m) { return glm::vec4(m.occlusionTexture.scale); }},
        {"alphaCutoff", 1, [](M m) { return glm::vec4(m.alphaCutoff); }},
        // ((ior - 1) / (ior + 1))^2; an IOR of 0 stands for an infinite one (F0 = 1)
        {"iorF0", 1, [](M m) {
             const float r = (m.ior - 1.0f) / (m.ior + 1.0f);
             return glm::vec4(m.ior == 0.0f ? 1.0f : r * r);
         }},
        {"specularFactor", 1, [](M m) { return glm::vec4(m.specular); }},
        {"specularColorFactor", 3, [](M m) { return glm::vec4(m.specularColor, 0.0f); }},
        {"sheenColorFactor", 3, [](M m) { return glm::vec4(m.sheen.color, 0.0f); }},
        {"sheenRoughnessFactor", 1, [](M m) { return glm::vec4(m.sheen.roughness); }},
        {"anisotropyStrength", 1, [](M m) { return glm::vec4(m.anisotropy.strength); }},
        // (cos, sin) of KHR_materials_anisotropy's rotation
        {"anisotropyRotation", 2, [](M m) {
             return glm::vec4(std::cos(m.anisotropy.rotation), std::sin(m.anisotropy.rotation), 0.0f, 0.0f);
         }},
        {"clearcoatFactor", 1, [](M m) { return glm::vec4(m.clearcoat.factor); }},
        {"clearcoatRoughnessFactor", 1, [](M m) { return glm::vec4(m.clearcoat.roughness); }},
        {"transmissionFactor", 1, [](M m) { return glm::vec4(m.transmission.factor); }},
        {"diffuseTransmissionFactor", 1, [](M m) { return glm::vec4(m.diffuseTransmission.factor); }},
        {"diffuseTransmissionColorFactor", 3, [](M m) { return glm::vec4(m.diffuseTransmission.color, 0.0f); }},
        {"iridescenceFactor", 1, [](M m) { return glm::vec4(m.iridescence.factor); }},
        {"iridescenceIor", 1, [](M m) { return glm::vec4(m.iridescence.ior); }},
        // KHR_materials_iridescence's minimum and maximum thickness, nm
        {"iridescenceThickness", 2, [](M m) {
             return glm::vec4(m.iridescence.thicknessMin, m.iridescence.thicknessMax, 0.0f, 0.0f);
         }},
    };
    return table;
}

std::string gltfUniformsGlsl() {
    static const char* const types[] = {"", "float", "vec2", "vec3", "vec4"};
    std::string glsl;
    for (const GltfUniform& u : gltfUniformTable()) glsl += std::string("uniform ") + types[u.components] + " " + u.name + ";\n";
    return glsl;
}

std::string gltfProgramPreamble(const Material& m, ShadowLookups shadows) {
    std::string defines = mapDefines(gltfMaps(m)) + alphaDefines(m);
    if (m.unlit) defines += "#define UNLIT\n";
    if (m.diffuseTransmission.factor > 0.0f) defines += "#define DIFFUSE_TRANSMISSION\n";
    return defines + shadowLookupDefines(shadows) + gltfUniformsGlsl();
}

std::unique_ptr<ShaderProgram> buildGltfProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"mesh_varyings.glsl", "frame.glsl", "lighting.glsl", "screen_door.glsl", "texture_maps.glsl",
                                 "normal_map.glsl", "gltf_iridescence.glsl", "gltf_bxdf.glsl", "gltf_inputs.glsl", "gltf.frag"},
        preamble);
}

std::unique_ptr<ShaderProgram> buildGltfShadowProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"mesh_varyings.glsl", "frame.glsl", "texture_maps.glsl", "gltf_iridescence.glsl",
                                 "gltf_bxdf.glsl", "gltf_inputs.glsl", "shadow_depth.glsl", "gltf_shadow.frag"},
        preamble);
}

void uploadGltfMaterial(const ShaderProgram& program, const Material& m, GpuTextures& textures, int firstUnit) {
    for (const GltfUniform& u : gltfUniformTable()) {
        const GLint location = program.uniform(u.name);
        const glm::vec4 v = u.value(m);
        switch (u.components) {
            case 1: glUniform1f(location, v.x); break;
            case 2: glUniform2f(location, v.x, v.y); break;
            case 3: glUniform3f(location, v.x, v.y, v.z); break;
            default: glUniform4f(location, v.x, v.y, v.z, v.w); break;
        }
    }
    textures.bindMaps(program, gltfMaps(m), firstUnit);
}

}  // namespace woven
