#include "shot_render.h"

namespace woven {

Image renderShotWith(const Shot& shot, const std::function<void(Material&)>& set, const FitRenderSettings& fit,
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
    if (fit.deadline != std::chrono::steady_clock::time_point::max()) {
        // RenderSettings::timeLimit ends the render after the pass that crosses it; a deadline
        // already passed still lets the first pass run, and is then cut there.
        const double left = std::chrono::duration<double>(fit.deadline - std::chrono::steady_clock::now()).count();
        settings.timeLimit = std::max(left, 1e-9);
    }
    RenderJob job(scene, settings);
    job.run(cancel);
    FilmImage frame = job.snapshot();
    if (frame.samples.count < fit.spp) return {};
    return std::move(frame.radiance);
}

Image renderShot(const Shot& shot, const WovenParams& params, const FitRenderSettings& fit,
                 const std::atomic<bool>& cancel) {
    return renderShotWith(shot, [&](Material& m) { m.woven = params; }, fit, cancel);
}

Image renderShotLambertian(const Shot& shot, const FitRenderSettings& fit, const std::atomic<bool>& cancel) {
    return renderShotWith(
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
