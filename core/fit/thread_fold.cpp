#include "thread_fold.h"

#include <cmath>

#include "weave_lattice.h"

namespace woven {

glm::dvec2 unfolded(const glm::dvec2& f) {
    const glm::dvec2 axis = std::abs(f.x) >= std::abs(f.y) ? glm::dvec2(f.x < 0.0 ? -1.0 : 1.0, 0.0)
                                                           : glm::dvec2(0.0, f.y < 0.0 ? -1.0 : 1.0);
    return axis - f;
}

UnfoldedThreads unfoldThreads(const Image& photo, const glm::dvec2& ends, const glm::dvec2& picks) {
    const auto best = [&](const glm::dvec2& e, const glm::dvec2& p) { return rankWeavesBySpectrum(photo, e, p).front().score; };
    UnfoldedThreads out{ends, picks};
    double bestScore = best(ends, picks) + kUnfoldLogLikelihood;
    for (int choice = 1; choice < 4; ++choice) {
        const bool unfoldEnds = choice & 1, unfoldPicks = choice & 2;
        if ((unfoldEnds && glm::length(unfolded(ends)) > kFinestUnfoldedThreads) ||
            (unfoldPicks && glm::length(unfolded(picks)) > kFinestUnfoldedThreads))
            continue;
        const glm::dvec2 e = unfoldEnds ? unfolded(ends) : ends, p = unfoldPicks ? unfolded(picks) : picks;
        const double score = best(e, p);
        if (score > bestScore) {
            bestScore = score;
            out = {e, p, unfoldEnds, unfoldPicks};
        }
    }
    return out;
}

}  // namespace woven
