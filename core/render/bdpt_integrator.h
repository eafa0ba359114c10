#pragma once
// Bidirectional path tracing after pbrt-v3 (Veach 1997, ch. 10): a camera subpath and a light
// subpath per sample, every (s, t) connection strategy, weighted by multiple importance sampling
// with the power heuristic through pbrt-v3's ratios of remapped reverse and forward densities.
// Strategies with t = 1 (light subpath vertices seen by the camera) land on other pixels and go
// to the film's splat buffer.
#include "integrator.h"

namespace woven {

class BdptIntegrator : public Integrator {
public:
    BdptIntegrator(const RenderScene& scene, const CameraModel& camera, int maxDepth, bool filterWeave)
        : scene_(scene), camera_(camera), maxDepth_(maxDepth), filterWeave_(filterWeave) {}

    glm::vec3 Li(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink) const override;

    struct Vertex;  // a subpath vertex (bdpt_integrator.cpp)

private:
    int cameraSubpath(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink, Vertex* path) const;
    int lightSubpath(Sampler& sampler, SampleSink& sink, Vertex* path) const;
    // path[0] is the subpath's vertex 1 (sample_dimensions.h); importance: a light subpath.
    int randomWalk(Ray ray, glm::vec3 beta, float pdf, int maxVertices, bool importance, Sampler& sampler,
                   SampleSink& sink, Vertex* path) const;
    // The contribution of strategy (s, t), MIS-weighted; for t = 1, *pRaster gets its pixel.
    glm::vec3 connect(Vertex* light, Vertex* camera, int s, int t, Sampler& sampler, SampleSink& sink,
                      glm::vec2* pRaster) const;
    float misWeight(const Vertex* light, const Vertex* camera, const Vertex& sampled, int s, int t) const;

    // Densities of pbrt-v3's Vertex, as functions of the scene.
    float convertDensity(const Vertex& from, float pdfSolidAngle, const Vertex& next) const;
    float pdf(const Vertex& v, const Vertex* prev, const Vertex& next) const;
    float pdfLight(const Vertex& v, const Vertex& next) const;
    float pdfLightOrigin(const Vertex& v, const Vertex& next) const;
    float infiniteLightDensity(const glm::vec3& dirFromLight) const;
    glm::vec3 Le(const Vertex& v, const Vertex& towards) const;
    bool isInfiniteLight(const Vertex& v) const;
    bool isDeltaLight(const Vertex& v) const;
    bool isConnectible(const Vertex& v) const;

    const RenderScene& scene_;
    const CameraModel& camera_;
    int maxDepth_;
    bool filterWeave_;
};

}  // namespace woven
