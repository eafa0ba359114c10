// The C++ parameter table and the GLSL struct stay one list: every wovenParamTable() entry is
// an active uniform of the surface program and every active `material.*` uniform is a table
// entry, uploads land in the right fields, and the shaders read every parameter (a new one
// the GLSL ignores fails here).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "gl_test_context.h"
#include "gltf_gl_material.h"
#include "woven_gl_material.h"

namespace woven::test {
namespace {

// Table entries the shader gets through WeaveTextures instead of reading a uniform: the weave
// (i, j, k) and `tile`, turned into a tile on the CPU by WeavePattern::fromParams, and the
// per-thread lists.
bool readThroughTextures(const ParamInfo& info) {
    return !isNumeric(info.type) || std::string(info.name) == "pattern";
}

Material everyFeature() {
    Material m;
    WovenParams p;
    p.noise = 0.3f;
    p.crimp = 0.4f;
    p.yarn_width = 0.8f;
    p.warp_width = 0.7f;
    m.woven = p;
    return m;
}

std::set<std::string> activeMaterialUniforms(GLuint program) {
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    std::set<std::string> names;
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLint size;
        GLenum type;
        glGetActiveUniform(program, GLuint(i), sizeof name, nullptr, &size, &type, name);
        const std::string n(name);
        if (n.rfind("material.", 0) == 0) names.insert(n.substr(9));
    }
    return names;
}

TEST(ShaderParams, EveryTableEntryIsAnActiveUniformAndNothingElse) {
    ensureHeadlessGl();
    const Material m = everyFeature();
    const auto program = buildWovenProgram(wovenProgramPreamble(m, true, ShadowLookups::Opaque));
    const std::set<std::string> active = activeMaterialUniforms(program->id());
    std::set<std::string> table;
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) continue;  // lists: textures, not uniforms
        table.insert(info.name);
        EXPECT_TRUE(active.count(info.name)) << "'" << info.name << "' is in wovenParamTable() but the shader never reads it";
    }
    for (const std::string& name : active) EXPECT_TRUE(table.count(name)) << "'material." << name << "' is not in wovenParamTable()";
}

TEST(ShaderParams, UploadedValuesReadBackPerField) {
    ensureHeadlessGl();
    Material m = everyFeature();
    WovenParams& p = *m.woven;
    // Distinct values per field, so a value landing in the wrong field is caught.
    p.pattern = {3, 2, 1};
    p.repeat = {7.0f, 9.0f};
    p.ex = 11.0f; p.ey = 13.0f; p.warp_ex = 17.0f; p.warp_ey = 19.0f;
    p.rs = 0.23f;
    p.weft_color = {0.1f, 0.2f, 0.3f};
    p.warp_color = {0.4f, 0.5f, 0.6f};
    p.cy = 0.29f; p.noise_scale = 0.31f; p.backing = 1;
    p.backing_color = {0.7f, 0.8f, 0.9f};
    const auto program = buildWovenProgram(wovenProgramPreamble(m, true, ShadowLookups::Opaque));
    glUseProgram(program->id());
    uploadWovenParams(*program, p);
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) continue;
        const GLint location = program->uniform((std::string("material.") + info.name).c_str());
        ASSERT_GE(location, 0) << info.name;
        const char* base = reinterpret_cast<const char*>(&p) + info.offset;
        const int n = info.type == ParamType::Vec2 ? 2 : (info.type == ParamType::Vec3 || info.type == ParamType::IVec3) ? 3 : 1;
        if (info.type == ParamType::Int || info.type == ParamType::IVec3) {
            GLint got[3] = {};
            glGetUniformiv(program->id(), location, got);
            for (int c = 0; c < n; ++c) EXPECT_EQ(got[c], reinterpret_cast<const int*>(base)[c]) << info.name << "[" << c << "]";
        } else {
            GLfloat got[3] = {};
            glGetUniformfv(program->id(), location, got);
            for (int c = 0; c < n; ++c) EXPECT_EQ(got[c], reinterpret_cast<const float*>(base)[c]) << info.name << "[" << c << "]";
        }
    }
}

// Mesa keeps every member of a uniform struct active even when the shader never reads it, so
// activity alone cannot tell whether the shader uses a parameter: the sources must read it.
TEST(ShaderParams, ShaderSourcesReadEveryTableEntry) {
    std::string sources;
    for (const char* file : {"yarn_geometry.glsl", "woven.frag"}) {
        std::ifstream in(shaderDirectory() + "/" + file);
        ASSERT_TRUE(in) << file;
        std::ostringstream s;
        s << in.rdbuf();
        sources += s.str();
    }
    for (const ParamInfo& info : wovenParamTable()) {
        if (readThroughTextures(info)) continue;
        const std::regex read("material\\." + std::string(info.name) + "\\b");
        EXPECT_TRUE(std::regex_search(sources, read)) << "no shader reads material." << info.name;
    }
}

// The glTF program's factors are one list too: gltfUniformTable() declares them in the preamble
// and uploads them, the shader sources read every entry and declare none by hand, and each
// upload lands in its uniform.
std::string gltfSources() {
    std::string sources;
    for (const char* file : {"gltf.frag", "gltf_inputs.glsl", "gltf_shadow.frag", "gltf_bxdf.glsl", "gltf_iridescence.glsl"}) {
        std::ifstream in(shaderDirectory() + "/" + file);
        EXPECT_TRUE(in) << file;
        std::ostringstream s;
        s << in.rdbuf();
        sources += s.str();
    }
    return sources;
}

TEST(GltfUniforms, TheSourcesReadEveryEntryAndDeclareNoFactorOfTheirOwn) {
    const std::string sources = gltfSources();
    for (const GltfUniform& u : gltfUniformTable())
        EXPECT_TRUE(std::regex_search(sources, std::regex(std::string("\\b") + u.name + "\\b")))
            << "no glTF shader reads " << u.name;
    // Besides the table's, only what the renderer sets for every surface program (the camera, the
    // emission) and the sheen's albedo table it binds are declared here.
    const std::set<std::string> shared = {"cameraPosition", "emission", "sheenAlbedoTable"};
    const std::regex declaration("uniform\\s+\\w+\\s+(\\w+)");
    for (std::sregex_iterator it(sources.begin(), sources.end(), declaration), end; it != end; ++it)
        EXPECT_TRUE(shared.count((*it)[1].str())) << "gltf shaders declare '" << (*it)[1].str()
                                                  << "' by hand: add it to gltfUniformTable()";
}

TEST(GltfUniforms, UploadedValuesReadBackPerEntry) {
    ensureHeadlessGl();
    Material m;
    // Distinct values per factor, so a value landing in the wrong uniform is caught.
    m.baseColor = {0.11f, 0.12f, 0.13f, 0.14f};
    m.metallic = 0.21f;
    m.roughness = 0.22f;
    m.normalTexture.scale = 0.23f;
    m.occlusionTexture.scale = 0.24f;
    m.alphaCutoff = 0.25f;
    m.ior = 1.7f;
    m.specular = 0.31f;
    m.specularColor = {0.32f, 0.33f, 0.34f};
    m.sheen.color = {0.41f, 0.42f, 0.43f};
    m.sheen.roughness = 0.44f;
    m.anisotropy.strength = 0.51f;
    m.anisotropy.rotation = 0.52f;
    m.clearcoat.factor = 0.61f;
    m.clearcoat.roughness = 0.62f;
    m.transmission.factor = 0.71f;
    m.diffuseTransmission.factor = 0.72f;
    m.diffuseTransmission.color = {0.73f, 0.74f, 0.75f};
    m.iridescence.factor = 0.81f;
    m.iridescence.ior = 1.31f;
    m.iridescence.thicknessMin = 120.0f;
    m.iridescence.thicknessMax = 380.0f;
    const auto program = buildGltfProgram(gltfProgramPreamble(m, ShadowLookups::Opaque));
    glUseProgram(program->id());
    GpuTextures textures;
    uploadGltfMaterial(*program, m, textures, 8);
    int active = 0;
    for (const GltfUniform& u : gltfUniformTable()) {
        const GLint location = program->uniform(u.name);
        if (location < 0) continue;  // compiled out for this material
        ++active;
        GLfloat got[4] = {};
        glGetUniformfv(program->id(), location, got);
        const glm::vec4 want = u.value(m);
        for (int c = 0; c < u.components; ++c) EXPECT_FLOAT_EQ(got[c], want[c]) << u.name << "[" << c << "]";
    }
    // Most factors shape every material; a table whose names the shader never declared reads none.
    EXPECT_GE(active, int(gltfUniformTable().size()) - 4);
}

}  // namespace
}  // namespace woven::test
