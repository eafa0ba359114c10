#pragma once
// The fit's render of a shot with trial woven parameters: a cheap frame through the renderer of
// `woven render` (render_job.h), at the photo's size, with few samples, direct light only (a flat
// swatch under a point light bounces no light onto itself) and a fixed seed, so that the loss is
// a deterministic function of the parameters.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>

#include "render_job.h"
#include "shot.h"

namespace woven {

struct FitRenderSettings {
    int spp = 4;
    uint64_t seed = 1;
    int threads = 0;  // 0: all cores
    // The render stops after the pass (one sample per pixel) that crosses it and then returns no
    // image, as one with fewer samples than the others is not comparable: how a fit keeps its
    // time budget (fitter.h).
    std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

// The shot rendered with each of its target's materials as `set` makes it. An empty image where
// `cancel` or the deadline cut it short.
Image renderShotWith(const Shot& shot, const std::function<void(Material&)>& set, const FitRenderSettings& settings,
                     const std::atomic<bool>& cancel);

// The raw render: no vignette or exposure (photo_model.h applies them). Every material the shot's
// target makes woven takes `params`. An empty image where `cancel` or the deadline cut it short.
Image renderShot(const Shot& shot, const WovenParams& params, const FitRenderSettings& settings,
                 const std::atomic<bool>& cancel);

// The same render with the target a white Lambertian plane (glTF's base colour 1, no specular
// reflection) in place of the cloth: what a fit that knew no weave would have, scaled.
Image renderShotLambertian(const Shot& shot, const FitRenderSettings& settings, const std::atomic<bool>& cancel);

}  // namespace woven
