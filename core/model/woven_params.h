#pragma once
// The one description of a woven material. The same field names are used in scene files,
// `woven bsdf-eval` JSON, the previewer's sliders and the GLSL uniform struct `WovenParams`
// (shaders/woven_params.glsl); wovenParamTable() lists them so every consumer iterates one table
// instead of keeping its own copy.
#include <glm/glm.hpp>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace woven {

// The parameters a thread's yarn has apart from its colour (MODEL.md section 6), in the order
// Yarn and YarnSpec keep them.
enum YarnField { kYarnEx, kYarnEy, kYarnRs, kYarnWidth, kYarnCy, kYarnNoise, kYarnTransmission, kYarnTransmissionGloss, kYarnFieldCount };

// A yarn type of WovenParams::yarns ("yarn type" in MODEL.md and the issue; YarnType in
// weave_pattern.h names the yarn on top): the yarn fields it sets. A field it leaves unset follows the
// material's parameter for the side the thread is on (`ex` for a pick, `warp_ex` for an end), so
// a draft's "thicker yarn" is {yarn_width} and still follows the exponents edited later.
struct YarnSpec {
    std::array<float, kYarnFieldCount> value{};
    std::array<bool, kYarnFieldCount> set{};
};
bool operator==(const YarnSpec& a, const YarnSpec& b);
inline bool operator!=(const YarnSpec& a, const YarnSpec& b) { return !(a == b); }

// Limits that keep a material's memory bounded (docs/DRAFTS.md): a tile of up to kMaxTileSide
// threads either way and kMaxTileCells cells; per-thread lists of up to kMaxThreadPeriod
// threads, which also bounds how often a side's lists repeat together.
constexpr int kMaxTileSide = 16384;  // what every OpenGL 4.1 GPU takes as a texture side
constexpr size_t kMaxTileCells = size_t(1) << 24;
constexpr int kMaxThreadPeriod = 65536;
constexpr int kMaxYarnTypes = 256;

struct WovenParams {
    // Weave: the regular (i, j, k) family of MODEL.md section 1. A non-empty `tile` (rows of
    // '-' weft / '|' warp, row V = 0 first) replaces it with a general binary tile.
    glm::ivec3 pattern{1, 1, 1};
    std::vector<std::string> tile;
    glm::vec2 repeat{1.0f, 1.0f};  // weave elements (threads, on average) per UV unit along u and v

    // Ashikhmin-Shirley lobe per yarn type (the source's D_t for weft, D_p for warp).
    float ex = 100.0f, ey = 2.0f;            // weft exponents: x along the yarn
    float warp_ex = 100.0f, warp_ey = 2.0f;  // warp exponents
    float rs = 0.04f;                        // specular reflectance at normal incidence
    glm::vec3 weft_color{0.55f, 0.12f, 0.10f};  // diffuse reflectance R_d, linear RGB
    glm::vec3 warp_color{0.55f, 0.12f, 0.10f};

    // Yarn geometry.
    float cy = 0.5f;          // cross-section curvature: 0 flat, 1 circular
    float yarn_width = 1.0f;  // weft width as a fraction of the element, (0, 1]
    float warp_width = 1.0f;  // warp width
    float crimp = 0.0f;       // rise and dip along floats, 0 = none

    // Variation and gaps.
    float noise = 0.0f;        // per-yarn colour noise amplitude, 0 = off
    float noise_scale = 0.5f;  // noise features per weave element along the yarn

    // Light through the yarns (docs/MODEL_TRANSMISSION.md): 0 = none, today's opaque yarns.
    float transmission = 0.0f;        // fraction of the light a yarn does not reflect that it passes
    float transmission_gloss = 0.5f;  // share of that light leaving forward along the fibres
    int backing = 0;           // 0: gaps are see-through; 1: gaps show backing_color
    glm::vec3 backing_color{0.0f, 0.0f, 0.0f};

    // Per thread (MODEL.md section 6): warp end U takes entry U mod size of each warp_ list,
    // weft pick V entry V mod size of each weft_ list. An empty list: every thread has the
    // material's value (warp_color, the warp's own exponents and width, even spacing).
    std::vector<glm::vec3> warp_colors, weft_colors;  // R_d, linear RGB
    std::vector<YarnSpec> yarns;                      // the yarn types warp_yarns, weft_yarns name
    std::vector<int> warp_yarns, weft_yarns;          // indices into yarns
    // Distance from a thread to the next, in any unit: only ratios count, as `repeat` gives the
    // mean number of threads per UV unit.
    std::vector<float> warp_spacing, weft_spacing;
};

// Reflection over WovenParams' fields: one entry per field, `tile` and the per-thread lists
// included. The numbers (Float ... IVec3) are GLSL uniforms and sliders; the lists go to the GPU
// as textures and are edited in the draft view.
enum class ParamType { Float, Int, Vec2, Vec3, IVec3, Rows, Vec3List, IntList, FloatList, YarnList };
// The threads a table entry sets a yarn field for (its `yarnField`): picks (ex), ends (warp_ex) or both (rs).
enum class YarnSide { None, Weft, Warp, Both };
struct ParamInfo {
    const char* name;
    ParamType type;
    size_t offset;      // offsetof(WovenParams, field)
    float min, max;     // valid range, per component (per element of a list)
    bool logScale;      // a slider for it should be logarithmic
    const char* label;  // the name the source paper and the GUI use
    // What it means, for docs/SCENE_FORMAT.md's table (generated from this table, which a test
    // checks) and the panel's tooltip.
    const char* description;
    const char* fallback;  // when absent from a file, take this field's value (e.g. warp_ex <- ex)
    // The yarn field this entry is the material's value of, for the threads of `yarnSide`; a
    // yarn type's JSON names its fields by the Weft or Both entries (ex, ey, rs, yarn_width, cy, noise, transmission, ...).
    int yarnField = -1;
    YarnSide yarnSide = YarnSide::None;
};
const std::vector<ParamInfo>& wovenParamTable();
// The number types, which are uniforms in GLSL and sliders in the panel (not Rows or lists).
bool isNumeric(ParamType t);

// Throws std::invalid_argument naming the first field that is out of range.
void validate(const WovenParams& p);

// Whether the material has per-thread colours, yarns or spacing (MODEL.md section 6).
bool hasThreadLists(const WovenParams& p);

}  // namespace woven
