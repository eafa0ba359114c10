#include "power_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <mutex>

namespace woven {

namespace {

// FFTW's planner is not thread-safe; executing a plan is.
std::mutex plannerMutex;

struct FftwDeleter {
    void operator()(void* p) const { fftwf_free(p); }
};

// Mean over a box of (2 r + 1)^2 pixels, clamped at the edges, by running sums (separable).
std::vector<float> boxMean(const std::vector<float>& v, int w, int h, int r) {
    std::vector<float> rows(v.size()), out(v.size());
    for (int y = 0; y < h; ++y) {
        double sum = 0.0;
        std::vector<double> prefix(size_t(w) + 1, 0.0);
        for (int x = 0; x < w; ++x) prefix[size_t(x) + 1] = (sum += v[size_t(y) * w + x]);
        for (int x = 0; x < w; ++x) {
            const int a = std::max(0, x - r), b = std::min(w, x + r + 1);
            rows[size_t(y) * w + x] = float((prefix[size_t(b)] - prefix[size_t(a)]) / (b - a));
        }
    }
    std::vector<double> prefix(size_t(h) + 1);
    for (int x = 0; x < w; ++x) {
        double sum = 0.0;
        for (int y = 0; y < h; ++y) prefix[size_t(y) + 1] = (sum += rows[size_t(y) * w + x]);
        for (int y = 0; y < h; ++y) {
            const int a = std::max(0, y - r), b = std::min(h, y + r + 1);
            out[size_t(y) * w + x] = float((prefix[size_t(b)] - prefix[size_t(a)]) / (b - a));
        }
    }
    return out;
}

}  // namespace

PowerSpectrum powerSpectrum(const std::vector<float>& values, int width, int height) {
    const int r = std::max(2, std::max(width, height) / 32);
    const std::vector<float> mean = boxMean(values, width, height, r);
    double floor = 0.0;
    for (float m : mean) floor += m;
    floor = 1e-3 * floor / double(std::max<size_t>(mean.size(), 1)) + 1e-12;  // a black corner divides by this

    const size_t nOut = size_t(height) * size_t(width / 2 + 1);
    std::unique_ptr<float[], FftwDeleter> in(static_cast<float*>(fftwf_malloc(sizeof(float) * size_t(width) * height)));
    std::unique_ptr<fftwf_complex[], FftwDeleter> out(static_cast<fftwf_complex*>(fftwf_malloc(sizeof(fftwf_complex) * nOut)));
    const auto hann = [](int n) {
        std::vector<double> w(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) w[size_t(i)] = 0.5 - 0.5 * std::cos(2.0 * M_PI * (i + 0.5) / n);
        return w;
    };
    const std::vector<double> windowX = hann(width), windowY = hann(height);
    double windowEnergy = 0.0;
    for (int y = 0; y < height; ++y) {
        const double wy = windowY[size_t(y)];
        for (int x = 0; x < width; ++x) {
            const double wx = windowX[size_t(x)];
            const size_t i = size_t(y) * width + x;
            in[i] = float(wx * wy * (values[i] / (mean[i] + floor) - 1.0));
            windowEnergy += wx * wx * wy * wy;
        }
    }
    fftwf_plan plan;
    {
        std::lock_guard<std::mutex> lock(plannerMutex);
        plan = fftwf_plan_dft_r2c_2d(height, width, in.get(), out.get(), FFTW_ESTIMATE);
    }
    fftwf_execute(plan);
    {
        std::lock_guard<std::mutex> lock(plannerMutex);
        fftwf_destroy_plan(plan);
    }
    PowerSpectrum s;
    s.width = width;
    s.height = height;
    s.power.resize(nOut);
    for (size_t i = 0; i < nOut; ++i)
        s.power[i] = float((double(out[i][0]) * out[i][0] + double(out[i][1]) * out[i][1]) / windowEnergy);
    return s;
}

namespace {

// Power at bin (kx, ky) of the whole plane: the neighbours across the half-plane's edge kx = 0
// are the conjugate bins; beyond the stored half, none.
double powerAtBin(const PowerSpectrum& s, int kx, int ky) {
    if (kx < 0) {
        kx = -kx;
        ky = -ky;
    }
    if (kx > s.width / 2) return 0.0;
    ky = ((ky % s.height) + s.height) % s.height;
    return s.at(kx, ky);
}

// The peak at bin (kx, ky), located to a fraction of a bin by a log-parabola through its
// neighbours: exact for a Gaussian peak, close for a Hann window's.
SpectralPeak peakAtBin(const PowerSpectrum& s, int kx, int ky) {
    const auto offset = [](double m, double c, double p) {
        const double lm = std::log(m + 1e-30), lc = std::log(c + 1e-30), lp = std::log(p + 1e-30);
        const double d = lm - 2.0 * lc + lp;
        return d < 0.0 ? std::clamp(0.5 * (lm - lp) / d, -0.5, 0.5) : 0.0;
    };
    const double c = powerAtBin(s, kx, ky);
    const double dx = offset(powerAtBin(s, kx - 1, ky), c, powerAtBin(s, kx + 1, ky));
    const double dy = offset(powerAtBin(s, kx, ky - 1), c, powerAtBin(s, kx, ky + 1));
    const int sy = ky <= s.height / 2 ? ky : ky - s.height;
    SpectralPeak peak;
    peak.frequency = glm::dvec2((kx + dx) / s.width, (sy + dy) / s.height);
    peak.power = c;
    return peak;
}

// Calls visit(kx, ky, f) for every stored bin within `halfAngle` of `direction` (unit) and
// between fMin and fMax cycles per pixel.
template <typename Visit>
void forEachBinWithin(const PowerSpectrum& s, const glm::dvec2& direction, double halfAngle, double fMin, double fMax,
                      Visit&& visit) {
    const int nx = s.width / 2 + 1;
    const double cosLimit = std::cos(halfAngle);
    for (int ky = 0; ky < s.height; ++ky) {
        const int sy = ky <= s.height / 2 ? ky : ky - s.height;
        for (int kx = 0; kx < nx; ++kx) {
            const glm::dvec2 f(double(kx) / s.width, double(sy) / s.height);
            const double fl = glm::length(f);
            if (fl < fMin || fl > fMax) continue;
            if (std::abs(glm::dot(f, direction)) < cosLimit * fl) continue;
            visit(kx, ky, f);
        }
    }
}

}  // namespace

std::vector<SpectralPeak> localPeaks(const PowerSpectrum& s, glm::dvec2 direction, double halfAngle, double fMin,
                                     double fMax) {
    const double len = glm::length(direction);
    if (!(len > 0.0)) return {};
    std::vector<SpectralPeak> peaks;
    forEachBinWithin(s, direction / len, halfAngle, fMin, fMax, [&](int kx, int ky, const glm::dvec2& f) {
        const double c = s.at(kx, ky);
        if (!(c > 0.0) || (kx == 0 && f.y < 0.0)) return;  // the column kx = 0 holds each bin and its conjugate
        // Ties go to the first bin in scan order, so that a flat top gives one peak.
        for (int dy = -kPeakRadiusBins; dy <= kPeakRadiusBins; ++dy)
            for (int dx = -kPeakRadiusBins; dx <= kPeakRadiusBins; ++dx) {
                if (dx == 0 && dy == 0) continue;
                const double n = powerAtBin(s, kx + dx, ky + dy);
                if (n > c || (n == c && (dy < 0 || (dy == 0 && dx < 0)))) return;
            }
        peaks.push_back(peakAtBin(s, kx, ky));
    });
    return peaks;
}

double powerNear(const PowerSpectrum& s, const glm::dvec2& f) {
    const glm::dvec2 g = f.x < 0.0 ? -f : f;  // the half-plane FFTW keeps
    const int cx = int(std::lround(g.x * s.width)), cy = int(std::lround(g.y * s.height));
    double best = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int kx = cx + dx, ky = cy + dy;
            if (kx < 0) {  // across kx = 0: the conjugate bin
                kx = -kx;
                ky = -ky;
            }
            if (kx > s.width / 2) continue;
            ky = ((ky % s.height) + s.height) % s.height;
            best = std::max(best, double(s.at(kx, ky)));
        }
    return best;
}

}  // namespace woven
