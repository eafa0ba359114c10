#pragma once
// The threads' fundamental frequencies in a photo of a swatch (docs/FIT.md, stage 1): one peak of
// the spectrum across the warp ends and one across the weft picks, chosen together. The camera
// says where each direction lies; the swatch may lie a few degrees turned, and it turns both.
#include <optional>

#include <glm/glm.hpp>

#include "power_spectrum.h"
#include "image.h"

namespace woven {

struct ThreadPeaks {
    std::optional<SpectralPeak> ends, picks;  // across u (warp ends) and across v (weft picks)
};

// The fundamentals of the threads whose directions the camera puts along `gradU` (U's gradient,
// per pixel: x right, y down) and `gradV`, each searched within `halfAngle` radians of its
// direction between fMin and fMax cycles per pixel.
//
// Narrow yarns with sharp edges put as much power in the harmonics as in the fundamental, and a
// pixel grid folds the harmonics above its Nyquist frequency back below it (at 4.7 pixels a
// thread the 4th harmonic lands at 0.67 of the fundamental's frequency, the 5th at a third of
// it), so the strongest peak is not always the thread. Each direction's candidates are the local
// maxima with at least a twentieth of its strongest peak's power, each scored by the power its
// first three harmonics hold, folded as the pixel grid folds them (the sum of their logs): a
// folded harmonic's own harmonics fall where the spectrum has little.
//
// A twill's or satin's spectrum is a 2-D lattice, and its high orders folded by the pixel grid
// land near either axis too, where their folded harmonics find the lattice's other points (the
// 512-pixel denim of bench_fit: a point 3.9 degrees off the ends' axis at 2.25 times their
// frequency outscored the ends' fundamental). A swatch turned on the table turns both
// directions alike, so the pair is chosen whose two turns (each peak's angle from its direction)
// agree within kThreadSkewDegrees, the best summed score among those pairs; where no pair agrees,
// or one direction has no peak, each direction's best alone.
ThreadPeaks threadFundamentals(const PowerSpectrum& spectrum, const glm::dvec2& gradU, const glm::dvec2& gradV,
                               double halfAngle, double fMin, double fMax);

// How far apart the two directions' turns may be: woven cloth's skew (the weft's departure from
// square to the warp) is within a degree or two on a swatch laid flat; the lattice's folded
// points that mislead the score lie farther off.
constexpr double kThreadSkewDegrees = 2.0;

// An image's thread fundamentals (threadFundamentals() on its luminance, within `halfAngle` of the
// directions `uvPerPixel` gives, at least 3 cycles across), each refined by the sharpest one-thread
// fold (tile_fold.h's refineThreadFrequency).
ThreadPeaks threadPeaks(const Image& image, const glm::dmat2& uvPerPixel, double halfAngle);

// How far the threads lie turned in the image from where the camera puts them: the mean of the
// found peaks' signed angles, radians, from the directions `uvPerPixel` gives (0 where neither
// was found).
double threadTurn(const ThreadPeaks& peaks, const glm::dmat2& uvPerPixel);

}  // namespace woven
