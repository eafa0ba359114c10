#pragma once
// The one description of a woven material. The same field names are used in scene files,
// `woven bsdf-eval` JSON, the previewer's sliders and the GLSL uniform struct `WovenParams`
// (shaders/woven_params.glsl); wovenParamTable() lists them so every consumer iterates one table
// instead of keeping its own copy.
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace woven {

struct WovenParams {
    // Weave: the regular (i, j, k) family of MODEL.md section 1. A non-empty `tile` (rows of
    // '-' weft / '|' warp, row V = 0 first) replaces it with a general binary tile.
    glm::ivec3 pattern{1, 1, 1};
    std::vector<std::string> tile;
    glm::vec2 repeat{1.0f, 1.0f};  // weave elements per UV unit along u and v

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
    int backing = 0;           // 0: gaps are see-through; 1: gaps show backing_color
    glm::vec3 backing_color{0.0f, 0.0f, 0.0f};
};

// Reflection over WovenParams' numeric fields (everything but `tile`).
enum class ParamType { Float, Int, Vec2, Vec3, IVec3 };
struct ParamInfo {
    const char* name;
    ParamType type;
    size_t offset;      // offsetof(WovenParams, field)
    float min, max;     // valid range, per component
    bool logScale;      // a slider for it should be logarithmic
    const char* label;  // the name the source paper and the GUI use
    const char* fallback;  // when absent from a file, take this field's value (e.g. warp_ex <- ex)
};
const std::vector<ParamInfo>& wovenParamTable();

// Throws std::invalid_argument naming the first field that is out of range.
void validate(const WovenParams& p);

}  // namespace woven
