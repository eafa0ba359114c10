#include "woven_gl_material.h"

#include <glm/gtc/type_ptr.hpp>

#include <sstream>
#include <vector>

#include "scene_description.h"
#include "weave_pattern.h"

namespace woven {

namespace {

const char* glslType(ParamType t) {
    switch (t) {
        case ParamType::Float: return "float";
        case ParamType::Int: return "int";
        case ParamType::Vec2: return "vec2";
        case ParamType::Vec3: return "vec3";
        case ParamType::IVec3: return "ivec3";
    }
    return "float";
}

// Fraction of the surface where (weft, warp) is seen, given the fraction of elements with warp
// on top: the top yarn covers its width across the element, the crossing yarn its own width of
// the rest (yarnAt's rule).
glm::vec2 coverageOf(float warpOnTop, float weftWidth, float warpWidth) {
    const float weftTop = 1.0f - warpOnTop;
    return {weftTop * weftWidth + warpOnTop * (1.0f - warpWidth) * weftWidth,
            warpOnTop * warpWidth + weftTop * (1.0f - weftWidth) * warpWidth};
}

}  // namespace

std::string wovenParamsGlslStruct() {
    std::ostringstream s;
    s << "struct WovenParams {\n";
    for (const ParamInfo& info : wovenParamTable()) s << "    " << glslType(info.type) << " " << info.name << ";\n";
    s << "};\n";
    return s.str();
}

std::string wovenFeatureDefines(const WovenParams& p, bool filterWeave) {
    std::string d;
    if (p.noise > 0.0f) d += "#define WOVEN_NOISE\n";
    if (p.crimp > 0.0f) d += "#define WOVEN_CRIMP\n";
    if (p.yarn_width < 1.0f && p.warp_width < 1.0f) d += "#define WOVEN_GAPS\n";
    if (filterWeave) d += "#define WOVEN_FILTER\n";
    return d;
}

bool readThroughWeaveTile(const ParamInfo& info) { return std::string(info.name) == "pattern"; }

void uploadWovenParams(const ShaderProgram& program, const WovenParams& p) {
    for (const ParamInfo& info : wovenParamTable()) {
        const GLint location = program.uniform((std::string("material.") + info.name).c_str());
        if (location < 0) continue;  // compiled out for this material
        const char* base = reinterpret_cast<const char*>(&p) + info.offset;
        const float* f = reinterpret_cast<const float*>(base);
        const int* i = reinterpret_cast<const int*>(base);
        switch (info.type) {
            case ParamType::Float: glUniform1f(location, *f); break;
            case ParamType::Int: glUniform1i(location, *i); break;
            case ParamType::Vec2: glUniform2fv(location, 1, f); break;
            case ParamType::Vec3: glUniform3fv(location, 1, f); break;
            case ParamType::IVec3: glUniform3iv(location, 1, i); break;
        }
    }
}

WeaveTileTexture::WeaveTileTexture() { glGenTextures(1, &texture_); }

WeaveTileTexture::~WeaveTileTexture() { glDeleteTextures(1, &texture_); }

void WeaveTileTexture::update(const WovenParams& p) {
    std::ostringstream key;
    key << p.pattern.x << ',' << p.pattern.y << ',' << p.pattern.z << ',' << p.yarn_width << ',' << p.warp_width;
    for (const std::string& row : p.tile) key << ',' << row;
    if (key.str() == key_) return;
    key_ = key.str();

    const WeavePattern front = WeavePattern::fromParams(p);
    const WeavePattern back = front.reversed();
    const int w = front.width(), h = front.height();
    std::vector<float> texels(size_t(w) * h * 4 * 2);
    int warpCells = 0;
    for (int face = 0; face < 2; ++face) {
        const WeavePattern& tile = face == 0 ? front : back;
        for (int V = 0; V < h; ++V)
            for (int U = 0; U < w; ++U) {
                float* t = &texels[((size_t(face) * h + V) * w + U) * 4];
                const bool warp = tile.top(U, V) == YarnType::Warp;
                const WeavePattern::Float f = tile.floatAt(U, V);
                t[0] = warp ? 1.0f : 0.0f;
                t[1] = float(f.position);
                t[2] = float(f.length);
                t[3] = 0.0f;
                if (face == 0) warpCells += warp;
            }
    }
    const float warpFraction = float(warpCells) / float(w * h);
    coverage_ = glm::vec4(coverageOf(warpFraction, p.yarn_width, p.warp_width),
                          coverageOf(1.0f - warpFraction, p.yarn_width, p.warp_width));

    glBindTexture(GL_TEXTURE_2D_ARRAY, texture_);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, w, h, 2, 0, GL_RGBA, GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

std::string wovenProgramPreamble(const WovenParams& params, bool filterWeave, bool shadows) {
    std::string defines = wovenFeatureDefines(params, filterWeave);
    if (shadows) defines += "#define PREVIEW_SHADOWS\n";
    return defines + wovenParamsGlslStruct();
}

std::unique_ptr<ShaderProgram> buildWovenProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"frame.glsl", "woven_params.glsl", "ashikhmin_shirley.glsl", "yarn_noise.glsl",
                                 "yarn_geometry.glsl", "lighting.glsl", "screen_door.glsl", "woven.frag"},
        preamble);
}

}  // namespace woven
