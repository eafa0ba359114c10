#include "twill_direction.h"

#include <cmath>

#include "luminance.h"
#include "power_spectrum.h"

namespace woven {

double twillLineDegrees(const Image& image) {
    std::vector<float> lum(image.pixels.size());
    for (size_t i = 0; i < lum.size(); ++i) lum[i] = luminance(image.pixels[i]);
    const PowerSpectrum s = powerSpectrum(lum, image.width, image.height);
    const double fMin = 3.0 / std::min(image.width, image.height);
    double strongest = 0.0, degrees = NAN;
    // Every peak within 45 degrees of either diagonal, in both half-planes' directions.
    for (const glm::dvec2 diagonal : {glm::dvec2(1.0, 1.0), glm::dvec2(1.0, -1.0)})
        for (const SpectralPeak& p : localPeaks(s, glm::normalize(diagonal), M_PI / 4.0, fMin, 0.5)) {
            const double a = std::atan2(p.frequency.y, p.frequency.x) * 180.0 / M_PI;
            const double fromAxis = std::abs(std::remainder(a, 90.0));
            if (fromAxis <= kOffAxisDegrees || p.power <= strongest) continue;
            strongest = p.power;
            degrees = std::remainder(a + 90.0, 180.0);  // the lines run across their peak
            if (degrees <= -90.0) degrees += 180.0;
        }
    return degrees;
}

}  // namespace woven
