#include "frame_denoise.h"

#include <iostream>

namespace woven {

Image denoiseBeauty(const Image& radiance, const RenderPasses& passes, const DenoiseSettings& settings) {
    DenoiseBuffers b;
    b.width = radiance.width;
    b.height = radiance.height;
    b.color = radiance.pixels;
    b.variance = passes.variance.pixels;
    b.albedo = passes.albedo.pixels;
    b.normal = passes.normal.pixels;
    b.depth = passes.depth;
    b.direct = passes.direct.pixels;
    b.directVariance = passes.directVariance.pixels;
    DenoiseResult result = denoise(b, settings);
    if (result.unusablePixels > 0)
        std::cerr << "warning: denoise: " << result.unusablePixels
                  << " pixels have a radiance or pass that is not finite; they are left as rendered\n";
    Image out = radiance;
    out.pixels = std::move(result.color);
    return out;
}

void denoiseFilm(FilmImage& film, const DenoiseSettings& settings) {
    film.denoised = denoiseBeauty(film.radiance, film.passes(), settings);
}

}  // namespace woven
