#pragma once
// The power a spectrum holds at each frequency where nothing periodic is: the median of each ring
// of bins at one |f|. Texture without a period (fibre fuzz, speckle, sensor noise, wrinkles, the
// light's remains) spreads its power over a whole ring, while threads put theirs in a few bins of
// it, so a peak's height over its ring's median tells threads from texture at any frequency, where
// raw power favours the coarse texture near the spectrum's centre. Spectral-maximum thread
// counting of canvas (Johnson et al., "Thread counting in paintings", Studies in Conservation 2011)
// looks for the threads' peak above the spectrum's background; this is that background, ring by
// ring.
#include <glm/glm.hpp>

#include <vector>

#include "power_spectrum.h"

namespace woven {

struct SpectralNoiseFloor {
    double binsPerCycle = 0.0;      // ring r holds the bins with round(|f| x binsPerCycle) = r
    std::vector<float> ringMedian;  // by ring
    // The median power of the ring at |f| (cycles per pixel); the last ring's beyond the spectrum.
    double at(const glm::dvec2& f) const;
};

// One pass over the spectrum, then a median per ring: linear in the spectrum's size.
SpectralNoiseFloor spectralNoiseFloor(const PowerSpectrum& spectrum);

}  // namespace woven
