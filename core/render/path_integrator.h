#pragma once
// Unidirectional path tracing: at every vertex, next-event estimation (one light chosen by
// power) and BSDF sampling, combined by multiple importance sampling with the power heuristic;
// Russian roulette after a few bounces.
#include "integrator.h"

namespace woven {

class PathIntegrator : public Integrator {
public:
    PathIntegrator(const RenderScene& scene, const CameraModel& camera, int maxDepth, bool filterWeave);

    glm::vec3 Li(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink) const override;

private:
    // Light sampled at hit, path vertex `vertex`, MIS-weighted against the BSDF's density; beta
    // excluded.
    glm::vec3 sampleOneLight(const SurfaceHit& hit, int vertex, const Bsdf& bsdf, const glm::vec3& wo,
                             Sampler& sampler, SampleSink& sink) const;

    const RenderScene& scene_;
    const CameraModel& camera_;
    int maxDepth_;
    bool filterWeave_;
    // Some light is not a point, spot or directional one: a ray can hit it.
    bool lightsHittable_ = false;
};

}  // namespace woven
