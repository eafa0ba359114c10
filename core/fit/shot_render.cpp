#include "shot_render.h"

#include <functional>

namespace woven {

namespace {

// The shot rendered with each target material as `set` makes it.
Image renderWith(const Shot& shot, const std::function<void(Material&)>& set, const FitRenderSettings& fit,
                 const std::atomic<bool>& cancel) {
    auto scene = std::make_shared<SceneDescription>(*shot.scene);
    for (int m : shot.materials) set(scene->materials[size_t(m)]);
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

}  // namespace

Image renderShot(const Shot& shot, const WovenParams& params, const FitRenderSettings& fit,
                 const std::atomic<bool>& cancel) {
    return renderWith(shot, [&](Material& m) { m.woven = params; }, fit, cancel);
}

Image renderShotLambertian(const Shot& shot, const FitRenderSettings& fit, const std::atomic<bool>& cancel) {
    return renderWith(
        shot,
        [](Material& m) {
            Material plane;
            plane.name = m.name;
            plane.doubleSided = m.doubleSided;
            plane.baseColor = glm::vec4(1.0f);
            plane.specular = 0.0f;
            plane.roughness = 1.0f;
            m = plane;
        },
        fit, cancel);
}

}  // namespace woven
