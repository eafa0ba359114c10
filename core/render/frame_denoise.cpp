#include "frame_denoise.h"

#include <iostream>

#include "denoiser.h"

namespace woven {

Image denoiseBeauty(const Image& radiance, const RenderPasses& passes) {
    DenoiseBuffers b;
    b.width = radiance.width;
    b.height = radiance.height;
    b.color = radiance.pixels;
    b.variance = passes.variance.pixels;
    b.albedo = passes.albedo.pixels;
    b.normal = passes.normal.pixels;
    b.depth = passes.depth;
    DenoiseResult result = denoise(b);
    if (result.unusablePixels > 0)
        std::cerr << "warning: denoise: " << result.unusablePixels
                  << " pixels have a radiance or pass that is not finite; they are left as rendered\n";
    Image out = radiance;
    out.pixels = std::move(result.color);
    return out;
}

void denoiseFilm(FilmImage& film) { film.denoised = denoiseBeauty(film.radiance, film.passes()); }

}  // namespace woven
