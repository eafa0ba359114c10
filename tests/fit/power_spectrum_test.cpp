// The spectrum's helpers the thread counter stands on (power_spectrum.h, spectral_noise_floor.h),
// on images drawn here: a sinusoid's peak where it is, and a ring's floor at its median.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "power_spectrum.h"
#include "spectral_noise_floor.h"

namespace woven {
namespace {

constexpr int kSide = 128;

// 1 + a cos(2 pi f . x) plus Gaussian noise of `noise`.
std::vector<float> stripes(const glm::dvec2& f, double a, double noise, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, noise);
    std::vector<float> v(size_t(kSide) * kSide);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x)
            v[size_t(y) * kSide + x] = float(1.0 + a * std::cos(2.0 * M_PI * (f.x * x + f.y * y)) + gauss(rng));
    return v;
}

TEST(PowerSpectrum, LocalPeaksFindAStripesFrequencyWithinATenthOfABin) {
    const glm::dvec2 f(0.2, 0.01);
    const PowerSpectrum s = powerSpectrum(stripes(f, 0.2, 0.0, 1), kSide, kSide);
    const std::vector<SpectralPeak> peaks = localPeaks(s, {1.0, 0.0}, 5.0 * M_PI / 180.0, 0.05, 0.45);
    ASSERT_FALSE(peaks.empty());
    const SpectralPeak* strongest = &peaks[0];
    for (const SpectralPeak& p : peaks)
        if (p.power > strongest->power) strongest = &p;
    EXPECT_NEAR(strongest->frequency.x, f.x, 0.1 / kSide);
    EXPECT_NEAR(strongest->frequency.y, f.y, 0.1 / kSide);
}

TEST(PowerSpectrum, LocalPeaksOutsideTheWedgeAreNotReported) {
    const PowerSpectrum s = powerSpectrum(stripes({0.0, 0.25}, 0.2, 0.0, 1), kSide, kSide);
    for (const SpectralPeak& p : localPeaks(s, {1.0, 0.0}, 5.0 * M_PI / 180.0, 0.05, 0.45))
        EXPECT_LT(p.power, 1e-3) << "at " << p.frequency.x << ", " << p.frequency.y;
}

// A spectrum laid out by hand: each ring's power 1 / (1 + r) but for a few spikes, which the
// ring's median leaves out.
TEST(SpectralNoiseFloor, EachRingsMedianLeavesItsPeaksOut) {
    PowerSpectrum s;
    s.width = s.height = kSide;
    const int nx = kSide / 2 + 1;
    s.power.resize(size_t(nx) * kSide);
    for (int ky = 0; ky < kSide; ++ky)
        for (int kx = 0; kx < nx; ++kx) {
            const int sy = ky <= kSide / 2 ? ky : ky - kSide;
            const double r = std::hypot(double(kx), double(sy));
            s.power[size_t(ky) * nx + kx] = float(1.0 / (1.0 + std::round(r)));
        }
    s.power[size_t(0) * nx + 30] = 1e3f;  // a thread's peak at 30 bins
    s.power[size_t(30) * nx + 0] = 1e3f;
    const SpectralNoiseFloor floor = spectralNoiseFloor(s);
    for (int r : {5, 30, 60}) EXPECT_FLOAT_EQ(floor.at({double(r) / kSide, 0.0}), float(1.0 / (1.0 + r))) << "ring " << r;
    EXPECT_FLOAT_EQ(floor.at({0.0, 10.0}), floor.ringMedian.back()) << "beyond the spectrum: the last ring";
}

}  // namespace
}  // namespace woven
