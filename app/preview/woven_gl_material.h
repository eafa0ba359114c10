#pragma once
// A woven material on the GPU: the GLSL declaration of `struct WovenParams` and the upload of
// every numeric field, both generated from core's wovenParamTable() so the C++ struct, the scene
// files, the sliders and the shader share one list; the weave and the per-thread lists as
// textures; the #defines that compile in only the features the material uses; what a glTF
// material made woven keeps of its surface (shaders/woven.frag).
#include <epoxy/gl.h>

#include <memory>
#include <optional>
#include <string>

#include "gpu_textures.h"
#include "shader_program.h"
#include "shadow_lookups.h"
#include "weave_coverage.h"  // Weave, WeaveCoverage
#include "woven_params.h"

namespace woven {

// "struct WovenParams { ivec3 pattern; vec2 repeat; ... };", one member per numeric table entry.
std::string wovenParamsGlslStruct();

// "#define WOVEN_NOISE\n..." for the features `p` uses (noise, crimp, see-through gaps,
// per-thread lists, uneven spacing) and the far-field weave filter when `filterWeave`.
std::string wovenFeatureDefines(const WovenParams& p, bool filterWeave);

// Sets uniform `material.<name>` for every numeric table entry the program uses.
void uploadWovenParams(const ShaderProgram& program, const WovenParams& p);

// The textures of a woven material (shaders/woven_params.glsl): the weave tile, its floats when
// the crimp needs them, the threads and yarns of core's Weave and their colours mipmapped for
// the weave filter; with the far-field weights (weaveCoverage()) of both faces.
class WeaveTextures {
public:
    WeaveTextures();
    ~WeaveTextures();
    WeaveTextures(const WeaveTextures&) = delete;
    WeaveTextures& operator=(const WeaveTextures&) = delete;

    // Rebuilds what `p` changed since the last update: the tile when the weave changed, the
    // thread and yarn tables (a few kilobytes) when anything about the threads did.
    void update(const WovenParams& p);
    // Binds the textures to units 0 (tile), 3 (floats), 4 (threads), 5 (yarns), 6 and 7 (the
    // filter's warp and weft colours), 14 (its warp-top table) and 15 (its colour tables) and sets
    // the uniforms that go with them.
    void bind(const ShaderProgram& program) const;

private:
    void updateTile(const Weave& weave);
    void updateThreads(const Weave& weave);
    void updateFootprintSplit(const Weave& weave, const WovenParams& p);

    GLuint tile_ = 0, floats_ = 0, threadBuffer_ = 0, threadTable_ = 0, yarnBuffer_ = 0, yarnTable_ = 0;
    GLuint colorTracks_[2] = {0, 0};  // warp, weft: the weave filter's mipmapped thread colours
    glm::ivec2 threadPeriod_{1}, threadSpaced_{0};
    WeaveCoverage coverage_[2];  // front, back
    // The far field's split by top yarn (WeaveFarField::footprintScales()): the table of warp-top
    // cells, and per face and colour the shares of the repeat, of warp-top and of other cells.
    GLuint warpTopSums_ = 0;  // the front face's
    bool splitsByFootprint_[2] = {false, false};
    glm::vec3 farShares_[2], inWarpCells_[2], inWeftCells_[2];
    // The front face's colour tables of the warp and the weft (WeaveFarField::footprintColors()),
    // one texture, and their sizes in cells (0 where unused).
    GLuint colorTopSums_ = 0;
    glm::ivec4 colorTableSizes_{0};
    std::optional<WovenParams> uploaded_;
};

// What a glTF material made woven keeps (Material::keptSurface) on the GPU: sets the base
// colour's alpha, the cutoff and the normal scale, and binds its base colour texture (the print,
// alpha) and normal map to units from `firstUnit` on; nothing for a material woven in its file.
void uploadKeptSurface(const ShaderProgram& program, const Material& material, GpuTextures& textures, int firstUnit);

// The woven program's preamble for a woven material: feature #defines and `shadows`' lookups,
// what it keeps of a glTF material (WOVEN_PRINT, MAP_<NAME>, ALPHA_MASK or ALPHA_BLEND), plus the
// WovenParams struct.
std::string wovenProgramPreamble(const Material& material, bool filterWeave, ShadowLookups shadows);
// shaders/mesh.vert + the woven.frag chain, compiled with `preamble`.
std::unique_ptr<ShaderProgram> buildWovenProgram(const std::string& preamble);

// Whether any of the weave's yarns lets light through (WOVEN_TRANSMISSION): its shadow is then
// coloured (ShadowMaps' transmittance pass).
bool yarnsTransmit(const WovenParams& p);
// The transmittance pass's program for a woven material whose yarns transmit (woven_shadow.frag),
// from wovenProgramPreamble(material, true, ShadowLookups::None): the weave filter's colour tracks
// give the mean thread colours.
std::unique_ptr<ShaderProgram> buildWovenShadowProgram(const std::string& preamble);

}  // namespace woven
