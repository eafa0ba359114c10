#pragma once
// The light at each pixel with the surface's colour divided out (irradiance = colour / albedo),
// which is what the denoiser smooths: the weave's threads are in the albedo pass, sharp and almost
// noise-free, so dividing them out leaves a signal that varies slowly across threads, and
// multiplying them back after the filter returns them untouched (as Cycles' NLM denoiser and
// Bitterli et al. 2016 do). Kept as three float planes per quantity, so the filter's inner loops
// run over contiguous floats.
#include <array>
#include <vector>

#include "denoise_buffers.h"

namespace woven {

struct Planes3 {
    std::array<std::vector<float>, 3> c;
    explicit Planes3(size_t n = 0) : c{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)} {}
};

struct Demodulated {
    Planes3 irradiance;  // colour / divisor
    Planes3 variance;    // its variance: the colour's over divisor^2 (the albedo taken as exact)
    Planes3 divisor;     // what was divided out, per channel, and is multiplied back
};

// Pixels that miss (albedo about 0: sky, lights, a frame without the pass) keep divisor 1; elsewhere
// each channel is divided by albedo + kAlbedoFloor, so that a nearly black thread (a backing of
// 0.02) does not blow its noise up a hundredfold. Unusable pixels (DenoiseBuffers::usable) get 0
// everywhere.
Demodulated demodulate(const DenoiseBuffers& buffers);

inline constexpr float kAlbedoFloor = 0.01f;

}  // namespace woven
