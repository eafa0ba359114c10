#include "integrator.h"

#include "footprint.h"

namespace woven {

void addFootprint(SurfaceHit& hit, const RenderScene& scene, const CameraModel& camera) {
    if (!scene.materials()[hit.material].filtersByFootprint()) return;
    const CameraModel::Footprint f = camera.footprint(hit.p, hit.ng);
    setUvFootprint(hit, f.dpdx, f.dpdy);
}

}  // namespace woven
