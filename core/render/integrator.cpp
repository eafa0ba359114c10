#include "integrator.h"

#include <stdexcept>

#include "bdpt_integrator.h"
#include "path_integrator.h"

namespace woven {

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const RenderScene& scene,
                                           const CameraModel& camera, int maxDepth) {
    if (name == "bdpt") return std::make_unique<BdptIntegrator>(scene, camera, maxDepth);
    if (name == "path") return std::make_unique<PathIntegrator>(scene, camera, maxDepth);
    throw std::invalid_argument("unknown integrator '" + name + "' (expected bdpt, path or auto)");
}

}  // namespace woven
