#pragma once
// A woven material on the GPU: the GLSL declaration of `struct WovenParams` and the upload of
// every field, both generated from core's wovenParamTable() so the C++ struct, the scene files,
// the sliders and the shader share one list; the weave tile of both faces as a texture; the
// #defines that compile in only the features the material uses.
#include <epoxy/gl.h>

#include <memory>
#include <string>

#include "shader_program.h"
#include "woven_params.h"

namespace woven {

// "struct WovenParams { ivec3 pattern; vec2 repeat; ... };", one member per table entry.
std::string wovenParamsGlslStruct();

// "#define WOVEN_NOISE\n..." for the features `p` uses (noise, crimp, see-through gaps) and the
// far-field weave filter when `filterWeave`.
std::string wovenFeatureDefines(const WovenParams& p, bool filterWeave);

// Table entries the shader gets through the weave tile texture instead of reading the uniform
// (the weave (i, j, k), turned into a tile on the CPU by WeavePattern::fromParams).
bool readThroughWeaveTile(const ParamInfo& info);

// Sets uniform `material.<name>` for every table entry the program uses.
void uploadWovenParams(const ShaderProgram& program, const WovenParams& p);

// The tile of the front and back faces as a 2-layer RGBA32F texture array (see
// shaders/woven_params.glsl), and the area each yarn type covers per face.
class WeaveTileTexture {
public:
    WeaveTileTexture();
    ~WeaveTileTexture();
    WeaveTileTexture(const WeaveTileTexture&) = delete;
    WeaveTileTexture& operator=(const WeaveTileTexture&) = delete;

    void update(const WovenParams& p);  // rebuilds only when the weave or the widths changed
    GLuint texture() const { return texture_; }
    // Fractions of the surface showing (weft, warp) on the front (xy) and back (zw) face.
    const glm::vec4& yarnCoverage() const { return coverage_; }

private:
    GLuint texture_ = 0;
    glm::vec4 coverage_{0.0f};
    std::string key_;
};

// The woven program's preamble for a material: feature #defines (PREVIEW_SHADOWS when
// `shadows`) plus the WovenParams struct.
std::string wovenProgramPreamble(const WovenParams& params, bool filterWeave, bool shadows);
// shaders/mesh.vert + the woven.frag chain, compiled with `preamble`.
std::unique_ptr<ShaderProgram> buildWovenProgram(const std::string& preamble);

}  // namespace woven
