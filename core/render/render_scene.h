#pragma once
// The scene as the integrators see it: one Embree 3 BVH over every triangle, its hits, its
// materials (SceneMaterials, which turn a hit into a BSDF) and its lights. Points a material lets
// rays through (woven gaps, alpha cut-outs, blended alpha) are skipped inside Embree's filter
// callbacks, so camera rays, bounces and shadow rays all pass through them the same way.
#include <memory>
#include <optional>
#include <vector>

#include "camera_model.h"
#include "bvh_light_sampler.h"
#include "light.h"
#include "scene_materials.h"

namespace woven {

// Camera rays pass through the back of single-sided surfaces (glTF's doubleSided false), as glTF
// viewers cull it; bounces and shadow rays meet both faces, as Cycles does (docs/MATERIALS.md).
enum class RayKind { Scattered, Camera };

class RenderScene {
public:
    // Throws SceneError (scene_loader.h) for what cannot be rendered: NaN vertices, no geometry.
    explicit RenderScene(std::shared_ptr<const SceneDescription> scene);
    // `scene` as an edit of `previous`'s: where only materials or lights changed (the same meshes,
    // positions, triangles and instances, whose materials let rays through and cull backs as
    // before) it takes previous's BVH and builds its materials and lights alone, as the rendered
    // viewport does for a slider; else it builds everything. Its frames are the constructor
    // above's, bit for bit. `previous` is left empty, fit only to be destroyed.
    RenderScene(std::shared_ptr<const SceneDescription> scene, RenderScene&& previous);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind = RayKind::Scattered) const;
    // Is the segment from a surface point to `target` blocked? The origin is offset off the
    // surface; the far end stops short of target by the same relative epsilon.
    bool occluded(const SurfaceHit& from, const glm::vec3& target) const;
    bool occludedToInfinity(const SurfaceHit& from, const glm::vec3& dir) const;
    // Whether a camera at `camera` sees from.p as its camera rays would: nothing in between, and not
    // the back of a single-sided surface (BDPT's light paths that end on the camera).
    bool seenFromCamera(const SurfaceHit& from, const glm::vec3& camera) const;

    // A ray leaving a hit in direction d, offset off the surface on d's side so that it cannot
    // re-hit the same triangle (no acne, no leaks at shading-normal edges).
    Ray spawnRay(const SurfaceHit& from, const glm::vec3& d) const;

    const SceneMaterials& materials() const;
    // Radiance the hit surface shows towards w: an area light's emission, or an unlit material's
    // colour (which is no light: lightIndex() is -1 there).
    glm::vec3 emitted(const SurfaceHit& hit, const glm::vec3& w) const;

    const std::vector<Light>& lights() const;
    // The lights whose light the direct-light pass shows (sample_contributions.h's FirstHit): those but the
    // environment (whose light only noisy sampling finds), at most kDirectPassLights of them,
    // the most powerful first.
    static constexpr int kDirectPassLights = 4;
    const std::vector<int>& directPassLights() const;
    int lightIndex(const SurfaceHit& hit) const;  // the area light of the hit triangle, or -1
    int environmentLight() const;                 // index of the environment light, or -1
    // Lights chosen by power alone (light_sampler.h), for samples taken from no point: BDPT's
    // light subpaths, and its strategies, whose weights must count them the same way.
    int sampleLight(float u, float* pmf) const;
    float lightPmf(int index) const;
    // Lights chosen by what each could send to ctx (bvh_light_sampler.h): the path tracer's.
    int sampleLight(const LightSampleContext& ctx, float u, float* pmf) const;
    float lightPmf(const LightSampleContext& ctx, int index) const;

    // What Embree holds: each mesh's triangles once, and one instance per copy of an instanced
    // mesh (Mesh::instances); an instanced scene's memory follows these, not the copies' triangles.
    struct GeometryCounts {
        size_t triangles = 0, instances = 0;
    };
    GeometryCounts geometryCounts() const;

    const Bounds& bounds() const;
    bool tookGeometry() const;  // built from a previous scene's BVH rather than its own
    const SceneDescription& description() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace woven
