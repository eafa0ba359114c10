#include "shot_render.h"

namespace woven {

Image renderShot(const Shot& shot, const WovenParams& params, const FitRenderSettings& fit,
                 const std::atomic<bool>& cancel) {
    auto scene = std::make_shared<SceneDescription>(*shot.scene);
    for (int m : shot.materials) scene->materials[size_t(m)].woven = params;
    RenderSettings settings = defaultRenderSettings(*scene);
    settings.spp = fit.spp;
    settings.seed = fit.seed;
    settings.threads = fit.threads;
    settings.maxDepth = 1;
    settings.noiseThreshold = 0.0;
    settings.integrator = "path";
    settings.renderPasses = false;
    RenderJob job(scene, settings);
    job.run(cancel);
    return job.snapshot().radiance;
}

}  // namespace woven
