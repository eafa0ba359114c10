#pragma once
// Threads finer than two pixels: the pixel grid folds a thread frequency F above its Nyquist
// frequency to e - F (e the axis it runs along, one cycle a pixel), where stage 1 finds it
// (docs/FIT.md, "Real photographs": twill4's picks, 1.56 pixels a thread, found at 2.7). The peak
// alone cannot tell F from e - F; the weave's lattice can: an (i, j, k) weave's peaks lie at
// a / P (ends + k picks), unfolded frequencies that the grid folds as it folds the threads, so
// only the true thread frequencies put a weave's lattice where the photo's spectrum has its peaks
// (weave_lattice.h).
#include <glm/glm.hpp>

#include "image.h"

namespace woven {

// The finest threads an unfolding may give, cycles per pixel: 1.33 pixels a thread, under which
// a phone's lens and demosaicing leave no contrast to fold.
constexpr double kFinestUnfoldedThreads = 0.75;
// How much more likely (in log) the best weave's lattice must be with a direction unfolded than
// as found: the shortlist's factor e^2 (weave_lattice.h), so a close call keeps the peak as found.
constexpr double kUnfoldLogLikelihood = 2.0;

struct UnfoldedThreads {
    glm::dvec2 ends{0.0}, picks{0.0};  // cycles per pixel, signed as given
    bool endsUnfolded = false, picksUnfolded = false;
};

// e - f for a peak f found along the pixel axis e nearest its direction: the frequency that the
// grid folds onto f, signed as f is.
glm::dvec2 unfolded(const glm::dvec2& f);

// The ends and picks (cycles per pixel, signed where U and V grow, as weave_lattice.h takes them)
// with each direction whose folded twin is no finer than kFinestUnfoldedThreads unfolded where
// that makes some weave's lattice lie on the photo's peaks kUnfoldLogLikelihood better.
UnfoldedThreads unfoldThreads(const Image& photo, const glm::dvec2& ends, const glm::dvec2& picks);

}  // namespace woven
