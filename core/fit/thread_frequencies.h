#pragma once
// The threads' fundamental frequencies in a photo of a swatch (docs/FIT.md, stage 1): one peak of
// the spectrum across the warp ends and one across the weft picks. The camera says where each
// direction lies; the swatch may lie a few degrees turned.
#include <optional>

#include <glm/glm.hpp>

#include "image.h"
#include "power_spectrum.h"
#include "spectral_noise_floor.h"

namespace woven {

struct ThreadPeaks {
    std::optional<SpectralPeak> ends, picks;  // across u (warp ends) and across v (weft picks)
};

// A peak of the spectrum near one thread direction, as the thread counter weighs it.
struct ThreadCandidate {
    SpectralPeak peak;
    double height = 0.0;  // its power over the noise floor of its ring (spectral_noise_floor.h)
    // The log of its height plus, for each of its next kThreadHarmonics - 1 harmonics (folded by
    // the pixel grid), the log of that harmonic's height over kLeastThreadPeakHeight where above
    // it: texture's harmonics add nothing, a narrow yarn's strong ones add much. A harmonic that
    // folds near zero frequency or onto a lower one counts nothing, so that a peak whose folded
    // harmonics land on itself gains nothing by it.
    double score = 0.0;
};

// Every local maximum of `spectrum` within `halfAngle` of `direction` (unit) between fMin and
// fMax, weighed: one scan of the spectrum, so linear in its size.
std::vector<ThreadCandidate> threadCandidates(const PowerSpectrum& spectrum, const SpectralNoiseFloor& noise,
                                              const glm::dvec2& direction, double halfAngle, double fMin, double fMax);

// The least height over the noise floor a peak needs to be taken for threads. A ring's bins
// without a period hold an exponentially distributed power, whose median is ln 2 of its mean:
// one exceeds 20 medians with a chance of exp(-13.9), 1e-6, so the few thousand bins searched
// give no false thread.
constexpr double kLeastThreadPeakHeight = 20.0;

// The least share of its direction's highest candidate a candidate needs to be weighed: a
// lattice of real cloth shows the weave's repeat a few times below its threads' frequency
// (twill4's backlit photo, docs/FIT.md: a 4-shaft twill's peaks at a quarter and a half of the
// ends' frequency, at 1/180 and 1/350 of their height), whose harmonics would outscore the
// threads', while a narrow yarn's fundamental stands within a tenth of its harmonics.
constexpr double kThreadHeightShare = 0.05;

// The highest thread frequency a photo is searched for, cycles per pixel: a phone's demosaicing
// leaves its own peaks along the axes near the Nyquist frequency (0.46 to 0.5 in the real photos),
// and threads finer than 2.2 pixels are not resolved.
constexpr double kHighestThreadFrequency = 0.45;

// The harmonics a candidate is weighed by. Narrow yarns with sharp edges put as much power in
// the harmonics as in the fundamental, and a pixel grid folds those above its Nyquist frequency
// back below it (at 4.7 pixels a thread the 4th harmonic lands at 0.67 of the fundamental's
// frequency, the 5th at a third of it), so the highest peak is not always the thread; a folded
// harmonic's own harmonics fall where the spectrum has little.
constexpr int kThreadHarmonics = 3;

// The fundamentals of the threads whose directions the camera puts along `gradU` (U's gradient,
// per pixel: x right, y down) and `gradV`, each searched within `halfAngle` radians of its
// direction between fMin and fMax cycles per pixel: each direction's contenders are the
// candidates that stand kLeastThreadPeakHeight over their ring's noise floor and
// kThreadHeightShare of its highest; at 2 to 4 pixels a thread the coarse texture of a real
// photo (fuzz, wrinkles, the light's remains) holds more raw power near the spectrum's centre
// than the threads do, but no peak that stands over its ring. Of the contenders, the best score,
// or the candidate over the noise floor whose 2nd or 3rd harmonic that is. A direction with no
// contender has no peak: the photo does not show its threads.
ThreadPeaks threadFundamentals(const PowerSpectrum& spectrum, const glm::dvec2& gradU, const glm::dvec2& gradV,
                               double halfAngle, double fMin, double fMax);

// An image's thread fundamentals (threadFundamentals() on its luminance, within `halfAngle` of the
// directions `uvPerPixel` gives, at least 3 cycles across), each refined by the sharpest one-thread
// fold (tile_fold.h's refineThreadFrequency).
ThreadPeaks threadPeaks(const Image& image, const glm::dmat2& uvPerPixel, double halfAngle);

// How far the threads lie turned in the image from where the camera puts them: the mean of the
// found peaks' signed angles, radians, from the directions `uvPerPixel` gives (0 where neither
// was found).
double threadTurn(const ThreadPeaks& peaks, const glm::dmat2& uvPerPixel);

}  // namespace woven
