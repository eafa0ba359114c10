#pragma once
// The 2-D power spectrum of one image channel (FFTW), which sees the weave's threads whatever
// their phase: threads of the photo and of a render never line up, their spectra do. The slow
// variation (the light's fall-off, the vignette) is removed first and the image windowed, so that
// what is left is the texture of the threads.
#include <glm/glm.hpp>

#include <vector>

namespace woven {

struct PowerSpectrum {
    int width = 0, height = 0;  // of the image
    // |F(kx, ky)|^2 for kx in [0, width / 2], ky in [0, height) (ky > height / 2 is negative),
    // normalised by the window's energy, so that images of different sizes compare.
    std::vector<float> power;
    float at(int kx, int ky) const { return power[size_t(ky) * size_t(width / 2 + 1) + size_t(kx)]; }
};

// `values` row by row, width x height. The channel divided by its mean over blocks of about a
// sixteenth of the image (a ratio, so that a brighter part of the cloth counts as much as a
// darker), minus 1, times a Hann window.
PowerSpectrum powerSpectrum(const std::vector<float>& values, int width, int height);

// A peak of the spectrum, located to a fraction of a bin by a log-parabola through its
// neighbours.
struct SpectralPeak {
    glm::dvec2 frequency{0.0};  // cycles per pixel along x, y
    double power = 0.0;
};

// Every local maximum of the spectrum (no bin within kPeakRadiusBins stronger) within
// `halfAngle` radians of `direction` (in pixels: x right, y down; either sign) between fMin and
// fMax cycles per pixel: one scan of the spectrum.
constexpr int kPeakRadiusBins = 2;
std::vector<SpectralPeak> localPeaks(const PowerSpectrum& spectrum, glm::dvec2 direction, double halfAngle, double fMin,
                                     double fMax);

// The largest power within a bin of frequency f (cycles per pixel, either half-plane).
double powerNear(const PowerSpectrum& spectrum, const glm::dvec2& f);

}  // namespace woven
