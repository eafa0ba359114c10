#include "spectral_noise_floor.h"

#include <algorithm>
#include <cmath>

namespace woven {

double SpectralNoiseFloor::at(const glm::dvec2& f) const {
    if (ringMedian.empty()) return 0.0;
    const size_t ring = size_t(std::lround(glm::length(f) * binsPerCycle));
    return ringMedian[std::min(ring, ringMedian.size() - 1)];
}

SpectralNoiseFloor spectralNoiseFloor(const PowerSpectrum& s) {
    SpectralNoiseFloor floor;
    if (s.width <= 0 || s.height <= 0) return floor;
    floor.binsPerCycle = double(std::max(s.width, s.height));
    // Rings out to the corner, |f| = sqrt(2) / 2.
    std::vector<std::vector<float>> rings(size_t(std::ceil(0.75 * floor.binsPerCycle)) + 1);
    const int nx = s.width / 2 + 1;
    for (int ky = 0; ky < s.height; ++ky) {
        const int sy = ky <= s.height / 2 ? ky : ky - s.height;
        for (int kx = 0; kx < nx; ++kx) {
            const glm::dvec2 f(double(kx) / s.width, double(sy) / s.height);
            const size_t ring = std::min(size_t(std::lround(glm::length(f) * floor.binsPerCycle)), rings.size() - 1);
            rings[ring].push_back(s.at(kx, ky));
        }
    }
    floor.ringMedian.resize(rings.size(), 0.0f);
    for (size_t r = 0; r < rings.size(); ++r) {
        std::vector<float>& ring = rings[r];
        if (ring.empty()) {
            floor.ringMedian[r] = r > 0 ? floor.ringMedian[r - 1] : 0.0f;
            continue;
        }
        std::nth_element(ring.begin(), ring.begin() + ring.size() / 2, ring.end());
        floor.ringMedian[r] = ring[ring.size() / 2];
    }
    return floor;
}

}  // namespace woven
