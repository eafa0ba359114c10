#include "integrator.h"

#include "footprint.h"

namespace woven {

void addFootprint(SurfaceHit& hit, const RenderScene& scene, const CameraModel& camera) {
    if (!scene.materials()[hit.material].filtersByFootprint()) return;
    const CameraModel::Footprint f = camera.footprint(hit.p, hit.ng);
    setUvFootprint(hit, f.dpdx, f.dpdy);
}

FirstHit firstHitOf(const SurfaceHit& hit, const std::optional<Bsdf>& bsdf, const glm::vec3& eye) {
    FirstHit f;
    f.depth = glm::length(hit.p - eye);
    f.normal = bsdf ? bsdf->shadingNormal() : hit.ns;
    if (bsdf) f.albedo = bsdf->albedo();
    return f;
}

}  // namespace woven
