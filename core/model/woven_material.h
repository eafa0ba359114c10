#pragma once
// A woven material ready to shade: its parameters plus its Weave (the tiles of both faces of the
// cloth, its threads and yarns), built once per material, so a hit only looks things up.
#include <optional>

#include "surface_bsdf.h"
#include "yarn_geometry.h"

namespace woven {

// The differential geometry a hit provides. `backSide`: the viewer is on the side opposite ns;
// the back of a weave shows the other yarn on top.
struct ShadingInput {
    glm::dvec2 uv{0.0};
    glm::vec3 ns{0, 0, 1};    // interpolated shading normal of the front face
    glm::vec3 dpdu{1, 0, 0};  // may be zero or parallel to ns (degenerate UVs): handled
    glm::vec3 dpdv{0, 1, 0};
    bool backSide = false;
};

struct WovenShading {
    YarnType yarn;
    SurfaceBsdf bsdf;
};

class WovenMaterial {
public:
    explicit WovenMaterial(const WovenParams& params);  // throws std::invalid_argument

    const WovenParams& params() const { return params_; }
    const WeavePattern& pattern(bool backSide) const { return weave_.pattern(backSide); }
    const Weave& weave() const { return weave_; }

    // nullopt where the point is a see-through gap: the ray passes on as through an alpha cut-out.
    std::optional<WovenShading> shade(const ShadingInput& in) const;
    // Cheap test for the ray-tracing filter: no yarn and no backing at this uv.
    bool isSeeThrough(const glm::dvec2& uv) const;
    // Whether any uv is see-through: both yarns narrower than their element, and no backing.
    bool hasSeeThroughGaps() const { return mayHaveGaps_; }

private:
    WovenParams params_;
    Weave weave_;
    bool mayHaveGaps_;
};

// The tangent frame (x along +u, y along +v, z = n) from possibly degenerate dp/du and dp/dv.
Frame tangentFrame(const glm::vec3& n, const glm::vec3& dpdu, const glm::vec3& dpdv);

}  // namespace woven
