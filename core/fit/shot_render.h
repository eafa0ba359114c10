#pragma once
// The fit's render of a shot with trial woven parameters: a cheap frame through the renderer of
// `woven render` (render_job.h), at the photo's size, with few samples, direct light only (a flat
// swatch under a point light bounces no light onto itself) and a fixed seed, so that the loss is
// a deterministic function of the parameters.
#include <atomic>
#include <cstdint>

#include "render_job.h"
#include "shot.h"

namespace woven {

struct FitRenderSettings {
    int spp = 4;
    uint64_t seed = 1;
    int threads = 0;  // 0: all cores
};

// The raw render: no vignette or exposure (photo_model.h applies them). Every material the shot's
// target makes woven takes `params`.
Image renderShot(const Shot& shot, const WovenParams& params, const FitRenderSettings& settings,
                 const std::atomic<bool>& cancel);

// The same render with the target a white Lambertian plane (glTF's base colour 1, no specular
// reflection) in place of the cloth: what a fit that knew no weave would have, scaled.
Image renderShotLambertian(const Shot& shot, const FitRenderSettings& settings, const std::atomic<bool>& cancel);

}  // namespace woven
