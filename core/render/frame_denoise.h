#pragma once
// A final frame's denoised beauty: its noisy mean radiance and its render passes (albedo, normal,
// depth, direct light, variance) handed to the denoiser of core/denoise (denoiser.h). What `woven render`,
// the Render button, `woven merge` and `woven converge` call on a finished frame; the frame file
// then shows the result as its beauty and keeps the noisy one beside it.
#include "denoiser.h"
#include "film.h"
#include "render_passes.h"

namespace woven {

// Pixels whose radiance is not finite are left as they are, with one warning line on stderr.
Image denoiseBeauty(const Image& radiance, const RenderPasses& passes, const DenoiseSettings& settings = {});

// film.denoised = the denoised film.radiance.
void denoiseFilm(FilmImage& film, const DenoiseSettings& settings = {});

}  // namespace woven
