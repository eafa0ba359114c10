#pragma once
// The render passes (AOVs) of a final frame beside its radiance, what a denoiser is guided by and
// compositors read: per pixel the mean over its camera samples of what their rays first hit
// (sample_contributions.h's FirstHit: albedo, shading normal, depth, direct light), and the variance of its mean
// radiance. A film and a frame file keep them as exact sums (PassSums), as they keep the
// radiance, so renders of disjoint sample ranges merge into the same passes bit for bit; the
// passes are computed from those sums (meanPasses()).
#include <vector>

#include "exact_sum.h"
#include "image.h"

namespace woven {

struct PassSums {
    ExactSum albedo[3], normal[3], direct[3], depth;
    // Per channel, each pass's estimate of the pixel squared (its camera sample with the splats
    // that landed on it, PassImage::combined()): with the radiance sums, the sample variance.
    ExactSum square[3];
    ExactSum directSquare;  // of the direct light's luminance, for the variance of its mean


    PassSums& operator+=(const PassSums& other);
    bool operator==(const PassSums& other) const;
    bool operator!=(const PassSums& other) const { return !(*this == other); }
};

struct RenderPasses {
    Image albedo;               // the first hit's BSDF albedo; 0 where rays hit nothing
    Image normal;               // the mean shading normal, made unit length (0 where nothing was hit)
    std::vector<float> depth;   // the mean distance from the camera, misses counting 0
    Image direct;               // the mean light from the lights straight by way of the first hit
    // Per channel, the variance of that mean: its luminance's, shared out in proportion to each
    // channel's share of the luminance (0 below 2 samples). Where in the pixel the samples fell
    // changes the light's brightness more than its colour, and the film keeps the squares of the
    // luminance alone.
    Image directVariance;
    Image variance;             // per channel, the variance of the pixel's mean radiance (0 below 2 samples)
};

// The passes of a width x height frame from its per-pixel sample counts, radiance sums (R, G, B
// per pixel) and pass sums. Throws std::invalid_argument when the sizes disagree.
RenderPasses meanPasses(int width, int height, const std::vector<float>& count,
                        const std::vector<ExactSum>& radianceSums, const std::vector<PassSums>& sums);

}  // namespace woven
