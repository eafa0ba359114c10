#pragma once
// What both integrators share: one camera sample in, a radiance estimate for its pixel out, plus
// contributions that land on other pixels (BDPT's t = 1 strategies) and a count of rays traced.
#include <cstdint>
#include <optional>
#include <vector>

#include "render_scene.h"
#include "sample_contributions.h"
#include "sample_dimensions.h"
#include "sampler.h"

namespace woven {

// Per-sample output besides the returned radiance. Owned by one tile, so no locking.
struct SampleSink {
    std::vector<Splat> splats;
    uint64_t rays = 0;  // intersection and shadow rays traced
    FirstHit firstHit;  // of the latest sample: set by Li(), reset by its caller before each
    // Whether Li() records firstHit: not where the film keeps no render passes, since the record
    // (a BSDF's albedo, a light's unshadowed contribution) costs a few per cent of a short path.
    bool recordsFirstHit = true;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // The radiance estimate of the camera ray through pRaster; all random numbers from sampler,
    // at the dimensions sample_dimensions.h gives each use.
    virtual glm::vec3 Li(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink) const = 0;
};

// Gives a hit its pixel footprint (CameraModel::footprint() through setUvFootprint()) where its
// material filters by one; other hits cost nothing more.
void addFootprint(SurfaceHit& hit, const RenderScene& scene, const CameraModel& camera);

// The render passes' record of a camera ray from `eye` that first hit `hit`, with its BSDF there
// (none: an emitter alone, albedo zero).
FirstHit firstHitOf(const RenderScene& scene, const SurfaceHit& hit, const std::optional<Bsdf>& bsdf, const glm::vec3& eye);

// Whether the BSDF at a hit may connect wo and wi. A reflecting BSDF only connects directions on
// the same side of the geometric surface, which keeps shading normals from leaking light (Veach
// 1997, 5.3); a transmitting one connects across it too, where its shading frame agrees.
inline bool connects(const SurfaceHit& hit, const Bsdf& bsdf, const glm::vec3& wo, const glm::vec3& wi) {
    const bool sameSide = sameGeometricSide(hit, wo, wi);
    if (!bsdf.transmits()) return sameSide;
    const glm::vec3& n = bsdf.shadingNormal();
    return sameSide == (glm::dot(wo, n) * glm::dot(wi, n) > 0.0f);
}

// The number that chooses one of the scene's lights for a light sample, at `dimension`: drawn
// only where there is a choice. The sampler's numbers are per dimension, so leaving it undrawn
// changes no other number of the path.
inline float lightChoiceNumber(const RenderScene& scene, Sampler& sampler, uint32_t dimension) {
    return scene.lights().size() > 1 ? sampler.get1D(dimension) : 0.0f;
}

// The number that chooses a BSDF's lobe for its sample, at `dimension`: drawn only where the BSDF
// has a choice to make, as lightChoiceNumber().
inline float lobeNumber(const Bsdf& bsdf, Sampler& sampler, uint32_t dimension) {
    return bsdf.choosesLobe() ? sampler.get1D(dimension) : 0.0f;
}

// The power heuristic (beta = 2) for one-sample densities f and g.
inline float powerHeuristic(float f, float g) {
    if (!(f > 0.0f)) return 0.0f;
    const float r = g / f;  // as a ratio, so large densities cannot overflow when squared
    return 1.0f / (1.0f + r * r);
}

}  // namespace woven
