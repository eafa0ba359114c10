#pragma once
// How far a render's statistics are from a photo's (image_stats.h): one error per statistic and
// their weighted sum, the loss the fit minimises. Each error is a mean square, so shots of any
// size weigh alike.
#include <array>

#include "image_stats.h"

namespace woven {

struct LossTerms {
    std::array<double, kStatGroupCount> error{};  // per statistic, unweighted
    double total = 0.0;                           // sum of weight x error
};

// Colours (block means, quantiles) as errors relative to the photo's mean of each channel, the
// Gram matrix relative to each of its entries, the spectrum in log10 of the power above the
// photo's median bin of that channel (below it are the photo's noise and the blur of its lens,
// which no fabric parameter should chase).
LossTerms loss(const ImageStats& photo, const ImageStats& render);

// Mean of ((render - photo) / the photo's channel mean)^2, for values laid out with the channel
// varying as (index / stride) % 3: the block means' and quantiles' error.
double colourError(const std::vector<float>& photo, const std::vector<float>& render, size_t stride);

// The mean of each channel (at least 1e-4) of values laid out with the channel varying as
// (index / stride) % 3: the scale the block means' and quantiles' errors are relative to.
glm::dvec3 channelMeans(const std::vector<float>& values, size_t stride);

// The weight of each statistic in LossTerms::total.
const std::array<double, kStatGroupCount>& lossWeights();

}  // namespace woven
