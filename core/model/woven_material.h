#pragma once
// A woven material ready to shade: its parameters plus its Weave (the tiles of both faces of the
// cloth, its threads and yarns), built once per material, so a hit only looks things up.
#include <optional>

#include "filtered_weave_lobe.h"
#include "surface_bsdf.h"
#include "yarn_transmission.h"
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
    // How uv changes from this pixel to the next along x and y at this point (the pixel's
    // footprint, from ray differentials): what the filtered BSDF averages over. Zero: a point.
    glm::dvec2 duvdx{0.0}, duvdy{0.0};
    // How far apart the values of the type uv was held in lie near it (uvSpacing(), a mesh's
    // float uv at large |uv|): the point is only known to within it, and shadeFiltered() covers
    // at least that as its footprint. Zero: exact.
    glm::dvec2 uvSpacing{0.0};
    // Multiplies the yarns' diffuse colour R_d (not the backing's): a glTF base colour texture
    // printed on the cloth. 1 leaves the model's colours exactly as they are.
    glm::vec3 print{1.0f};
};

struct WovenShading {
    YarnType yarn;
    SurfaceBsdf bsdf;
    // The light the point passes to the other side, in its own frame: the same lobe whichever
    // face is seen, so that it is reciprocal (docs/MODEL_TRANSMISSION.md section 3);
    // transmittingYarn() composes it with bsdf. Absent where a yarn of transmission 0 is on
    // either face: the point stays exactly the reflecting lobe of before.
    std::optional<FramedLobe<YarnTransmission>> transmission = std::nullopt;
};

class WovenMaterial {
public:
    explicit WovenMaterial(const WovenParams& params);  // throws std::invalid_argument

    const WovenParams& params() const { return params_; }
    const WeavePattern& pattern(bool backSide) const { return weave_.pattern(backSide); }
    const Weave& weave() const { return weave_; }

    // nullopt where the point is a see-through gap: the ray passes on as through an alpha cut-out.
    std::optional<WovenShading> shade(const ShadingInput& in) const;
    // The BSDF filtered over the footprint (in.duvdx, in.duvdy, at least in.uvSpacing; MODEL.md
    // section 7) where it covers a quarter of a weave element or more, in the tangent frame;
    // nullopt where it is smaller (shade() is the model there) or the point is a see-through gap.
    std::optional<FramedLobe<FilteredWeaveLobe>> shadeFiltered(const ShadingInput& in) const;
    // The far field of a face, for the filtered BSDF and the preview's twin.
    const WeaveFarField& farField(bool backSide) const { return farField_[backSide ? 1 : 0]; }
    // Cheap test for the ray-tracing filter: no yarn and no backing at this uv.
    bool isSeeThrough(const glm::dvec2& uv) const;
    // Whether any uv is see-through: both yarns narrower than their element, and no backing.
    bool hasSeeThroughGaps() const { return mayHaveGaps_; }
    // Whether any yarn type has transmission > 0: only then may shade() give a transmission.
    bool transmits() const { return transmits_; }

private:
    WovenParams params_;
    Weave weave_;
    WeaveFarField farField_[2];  // front, back
    bool mayHaveGaps_, transmits_;

    // shade() in a given tangent frame (x = +u, y = +v, z = the normal of the face seen).
    std::optional<WovenShading> shade(const ShadingInput& in, const Frame& tangent) const;
};

// The tangent frame (x along +u, y along +v, z = n) from possibly degenerate dp/du and dp/dv.
Frame tangentFrame(const glm::vec3& n, const glm::vec3& dpdu, const glm::vec3& dpdv);

}  // namespace woven
