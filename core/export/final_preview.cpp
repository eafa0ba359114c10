#include "final_preview.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "display_transform.h"
#include "frame_denoise.h"
#include "render_job.h"
#include "scene_lighting.h"

namespace woven {

TextureImage renderFinalPreview(const SceneDescription& scene, int longerSide, int spp) {
    SceneDescription lit = scene;
    lightByDefault(lit);
    RenderSettings settings = defaultRenderSettings(lit);
    const double aspect = double(settings.width) / double(settings.height);
    settings.width = aspect >= 1.0 ? longerSide : std::max(1, int(std::lround(longerSide * aspect)));
    settings.height = aspect >= 1.0 ? std::max(1, int(std::lround(longerSide / aspect))) : longerSide;
    settings.spp = spp;
    RenderJob job(std::make_shared<const SceneDescription>(lit), settings);
    const std::atomic<bool> cancel{false};
    job.run(cancel);
    FilmImage film = job.snapshot();
    denoiseFilm(film);
    TextureImage t;
    t.width = film.radiance.width, t.height = film.radiance.height;
    for (const glm::vec3& p : film.denoised ? film.denoised->pixels : film.radiance.pixels) {
        const glm::u8vec3 c = displayColor(p, {});
        t.bytes.emplace_back(c.r, c.g, c.b, 255);
    }
    return t;
}

}  // namespace woven
