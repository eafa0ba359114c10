#include "integrator.h"

#include <stdexcept>

#include "footprint.h"

#include "bdpt_integrator.h"
#include "path_integrator.h"

namespace woven {

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const RenderScene& scene,
                                           const CameraModel& camera, int maxDepth, bool filterWeave) {
    if (name == "bdpt") return std::make_unique<BdptIntegrator>(scene, camera, maxDepth, filterWeave);
    if (name == "path") return std::make_unique<PathIntegrator>(scene, camera, maxDepth, filterWeave);
    throw std::invalid_argument("unknown integrator '" + name + "' (expected bdpt, path or auto)");
}

void addFootprint(SurfaceHit& hit, const RenderScene& scene, const CameraModel& camera) {
    if (!scene.materials()[hit.material].filtersByFootprint()) return;
    const CameraModel::Footprint f = camera.footprint(hit.p, hit.ng);
    setUvFootprint(hit, f.dpdx, f.dpdy);
}

}  // namespace woven
