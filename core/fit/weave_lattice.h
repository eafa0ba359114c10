#pragma once
// Which weave a photo shows, from where its spectrum has peaks (docs/FIT.md, "How it fits"). An
// (i, j, k) weave (MODEL.md section 1) is a function of d = (U + k V) mod P, P = i + j, so its
// pattern's spectrum is zero but on the lattice (p, q) = (a / P, a k / P) mod 1 cycles per weave
// element, a = 1 ... P - 1, with amplitude |sin(pi a i / P) / sin(pi a / P)| / P; the yarns'
// cross-sections and colours only scale those peaks. Once the thread frequencies are known, each
// candidate's lattice is known in the photo's pixels, and the weave is the candidate whose
// lattice is where the photo has peaks and nowhere else. A weave and its complement ((1, 3, 1)
// and (3, 1, 1)) have the same lattice: which yarn faces the cloth is for the colours to tell.
#include <glm/glm.hpp>

#include <vector>

#include "image.h"

namespace woven {

struct WeaveLatticeScore {
    glm::ivec3 pattern;
    // log-likelihood of the photo's peaks and gaps under this weave's lattice: higher is better.
    double score = 0.0;
};

// Each of weaveCandidates() scored on the photo's spectra (R, G and B), best first (ties keep
// the candidates' order). `ends` and `picks`: the thread frequencies, cycles per pixel along x
// and y, of one cycle per element along U (warp ends) and along V (weft picks), each signed so
// that it points where U (or V) grows.
std::vector<WeaveLatticeScore> rankWeavesBySpectrum(const Image& photo, const glm::dvec2& ends, const glm::dvec2& picks);

// The weaves of `ranking` worth fitting colours to: those within a factor e^2 (7) in likelihood
// of the best, so a weave and its complement (one lattice) and a close second lattice, not the
// lattices a clear peak or gap rules out (each costs a factor of about 20 or more).
std::vector<glm::ivec3> weaveShortlist(const std::vector<WeaveLatticeScore>& ranking);

}  // namespace woven
