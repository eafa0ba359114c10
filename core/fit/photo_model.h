#pragma once
// How a photograph relates to a render of the same shot (docs/FIT.md): the encoding of its
// values, the lens's vignette, and the exposure. The fit applies the vignette and exposure to
// its renders, so that it compares the photo with what the camera would have recorded.
#include <vector>

#include "scene_description.h"

namespace woven {

// The photo's pixels as linear RGB: sRGB or gamma 2.2 decoded, or taken as they are
// ("linear"; float formats always). Throws ImageError naming the file, also for a photo with
// nothing to fit: a pixel that is not a finite number (the loss would be inf), or every pixel
// within 1% of the mean (a uniform grey, or all clipped, was fitted as some weave); all black is
// data (an opaque cloth lit from behind).
Image readPhoto(const ShotPhoto& photo);

// The largest value the photo's file can hold: 1 where it is 8- or 16-bit (a highlight brighter
// than the sensor's full scale is clipped there), infinite for EXR and HDR.
float photoSaturation(const ShotPhoto& photo);

// The render darkened toward the corners by the Gaussian of `sigmaPx` pixels about the image
// centre; unchanged for sigmaPx = 0.
void applyVignette(Image& image, float sigmaPx);

// The exposure s minimising sum |photo_i - s render_i|^2 over paired values (block means of
// every shot whose exposure is free): one scale for all of them.
double bestExposure(const std::vector<float>& photo, const std::vector<float>& render);

// `image` times `exposure`, clipped at `saturation` as the photo's file clips.
void expose(Image& image, float exposure, float saturation);

}  // namespace woven
