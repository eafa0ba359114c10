#include "tile_fold.h"

#include <array>
#include <cmath>
#include <complex>

#include "luminance.h"

namespace woven {

namespace {

// Bins across a thread: enough to see its centre, its edges and the gap between. A pixel covers
// a fifth to a quarter of a thread in the rig, and pixels fall at every phase of the threads over
// the image's many repeats, so finer bins would still fill but hold mostly the pixels' own blur.
constexpr int kFoldBinsPerThread = 4;

// The phase, in cycles, at which the luminance's component of frequency f peaks: the fold's
// origin. The image's mean is taken off and a Hann window applied first, so that neither the
// mean nor the image's edges leak into a component of a few dozen cycles.
double peakPhase(const std::vector<float>& lum, int width, int height, double mean, const glm::dvec2& f) {
    std::complex<double> c(0.0);
    for (int y = 0; y < height; ++y) {
        const double wy = 0.5 - 0.5 * std::cos(2.0 * M_PI * (y + 0.5) / height);
        for (int x = 0; x < width; ++x) {
            const double wx = 0.5 - 0.5 * std::cos(2.0 * M_PI * (x + 0.5) / width);
            const double theta = 2.0 * M_PI * (f.x * (x + 0.5) + f.y * (y + 0.5));
            c += wx * wy * (double(lum[size_t(y) * size_t(width) + size_t(x)]) - mean) * std::polar(1.0, -theta);
        }
    }
    return std::arg(c) / (2.0 * M_PI);
}

// Bins across one thread of the sharpness measure: its variance grows with the bins until they
// resolve the profile, which a pixel of a fifth of a thread blurs.
constexpr int kProfileBins = 16;

double profileVariance(const std::vector<float>& values, int width, int height, const glm::dvec2& f) {
    std::array<double, kProfileBins> sum{}, weight{};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double t = f.x * (x + 0.5) + f.y * (y + 0.5);
            const double b = (t - std::floor(t)) * kProfileBins - 0.5;
            const int b0 = int(std::floor(b));
            const double fb = b - b0;
            const double v = values[size_t(y) * size_t(width) + size_t(x)];
            const size_t i0 = size_t((b0 + kProfileBins) % kProfileBins), i1 = size_t((b0 + 1 + kProfileBins) % kProfileBins);
            sum[i0] += (1.0 - fb) * v;
            weight[i0] += 1.0 - fb;
            sum[i1] += fb * v;
            weight[i1] += fb;
        }
    double mean = 0.0, total = 0.0;
    for (int i = 0; i < kProfileBins; ++i) {
        mean += sum[size_t(i)];
        total += weight[size_t(i)];
    }
    mean /= std::max(total, 1e-30);
    double var = 0.0;
    for (int i = 0; i < kProfileBins; ++i) {
        if (weight[size_t(i)] <= 0.0) continue;
        const double d = sum[size_t(i)] / weight[size_t(i)] - mean;
        var += weight[size_t(i)] * d * d;
    }
    return var / std::max(total, 1e-30);
}

// The t in [lo, hi] of the largest g(t): a scan for the highest of `steps` points (the variance
// has side lobes where the fold drifts by whole threads), then golden sections about it.
template <class G>
double maximise(const G& g, double lo, double hi, int steps) {
    double best = lo, bestValue = -INFINITY;
    for (int i = 0; i <= steps; ++i) {
        const double t = lo + (hi - lo) * i / steps;
        const double v = g(t);
        if (v > bestValue) {
            bestValue = v;
            best = t;
        }
    }
    const double step = (hi - lo) / steps;
    double a = best - step, b = best + step;
    const double r = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - r * (b - a), d = a + r * (b - a), gc = g(c), gd = g(d);
    for (int i = 0; i < 24; ++i) {
        if (gc > gd) {
            b = d;
            d = c;
            gd = gc;
            c = b - r * (b - a);
            gc = g(c);
        } else {
            a = c;
            c = d;
            gc = gd;
            d = a + r * (b - a);
            gd = g(d);
        }
    }
    return 0.5 * (a + b);
}

// The fold's origin, in threads along U and V: where the luminance's components at the grid's
// two frequencies peak.
glm::dvec2 foldPhase(const Image& image, const ThreadGrid& grid) {
    std::vector<float> l(image.pixels.size());
    double mean = 0.0;
    for (size_t i = 0; i < l.size(); ++i) mean += l[i] = luminance(image.pixels[i]);
    mean /= double(std::max<size_t>(l.size(), 1));
    return {peakPhase(l, image.width, image.height, mean, grid.ends), peakPhase(l, image.width, image.height, mean, grid.picks)};
}

// The circular shift, in bins, that lays a render's fold on a photo's: bin (u, v) of the photo's
// against bin (u + u', v + v') of the render's.
struct FoldShift {
    int u = 0, v = 0;
};

size_t shiftedBin(const TileFold& fold, int u, int v, const FoldShift& shift) {
    const int n = fold.side;
    return size_t((v + shift.v) % n) * size_t(n) + size_t((u + shift.u) % n);
}

// The shift whose luminance matches best.
FoldShift alignFolds(const TileFold& photo, const TileFold& render) {
    FoldShift best;
    if (photo.side == 0 || photo.side != render.side) return best;
    const int n = photo.side;
    // Every shift, not only whole threads from the fundamentals' peaks: those are the same place
    // of the weave in both only while the yarns' colours order alike.
    double bestError = INFINITY;
    for (int sv = 0; sv < n; ++sv)
        for (int su = 0; su < n; ++su) {
            const FoldShift shift{su, sv};
            double e = 0.0;
            for (int v = 0; v < n; ++v)
                for (int u = 0; u < n; ++u) {
                    const size_t p = size_t(v) * size_t(n) + size_t(u), r = shiftedBin(render, u, v, shift);
                    if (photo.weight[p] <= 0.0f || render.weight[r] <= 0.0f) continue;
                    const double d = double(luminance(render.mean[r])) - luminance(photo.mean[p]);
                    e += d * d;
                }
            if (e < bestError) {
                bestError = e;
                best = shift;
            }
        }
    return best;
}

// The fold of `image` with its origin at `phase` (threads along U and V).
TileFold foldAtPhase(const Image& image, const ThreadGrid& grid, const glm::dvec2& phase) {
    TileFold fold;
    if (image.pixels.empty() || grid.period < 1) return fold;
    fold.side = kFoldBinsPerThread * grid.period;
    const size_t bins = size_t(fold.side) * size_t(fold.side);
    std::vector<glm::dvec3> sum(bins, glm::dvec3(0.0));
    std::vector<double> weight(bins, 0.0);
    const double phaseU = phase.x, phaseV = phase.y;

    const double period = grid.period;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            // In bins, the bins' centres at whole numbers: each pixel is shared by the four
            // bins around it, so that the fold changes smoothly with the grid.
            auto binCoordinate = [&](const glm::dvec2& f, double phase) {
                const double t = glm::dot(f, p) + phase;
                return (t - period * std::floor(t / period)) * kFoldBinsPerThread - 0.5;
            };
            const double bu = binCoordinate(grid.ends, phaseU), bv = binCoordinate(grid.picks, phaseV);
            const int u0 = int(std::floor(bu)), v0 = int(std::floor(bv));
            const double fu = bu - u0, fv = bv - v0;
            const glm::dvec3 c(image.at(x, y));
            for (int dv = 0; dv < 2; ++dv)
                for (int du = 0; du < 2; ++du) {
                    const int u = (u0 + du + fold.side) % fold.side, v = (v0 + dv + fold.side) % fold.side;
                    const double w = (du ? fu : 1.0 - fu) * (dv ? fv : 1.0 - fv);
                    const size_t b = size_t(v) * size_t(fold.side) + size_t(u);
                    sum[b] += w * c;
                    weight[b] += w;
                }
        }
    fold.mean.resize(bins);
    fold.weight.resize(bins);
    for (size_t b = 0; b < bins; ++b) {
        fold.weight[b] = float(weight[b]);
        fold.mean[b] = weight[b] > 0.0 ? glm::vec3(sum[b] / weight[b]) : glm::vec3(0.0f);
    }
    return fold;
}

}  // namespace

glm::dvec3 foldChannelMeans(const TileFold& photo) {
    glm::dvec3 sum(0.0);
    double total = 0.0;
    for (size_t b = 0; b < photo.mean.size(); ++b) {
        sum += double(photo.weight[b]) * glm::dvec3(photo.mean[b]);
        total += photo.weight[b];
    }
    return glm::max(sum / std::max(total, 1e-30), glm::dvec3(1e-4));
}

glm::dvec2 refineThreadFrequency(const std::vector<float>& values, int width, int height, const glm::dvec2& f) {
    const double length = glm::length(f);
    if (!(length > 0.0) || values.size() != size_t(width) * size_t(height)) return f;
    double scale = 1.0, angle = 0.0;
    auto frequency = [&](double s, double a) {
        const double c = std::cos(a), sn = std::sin(a);
        return s * glm::dvec2(c * f.x - sn * f.y, sn * f.x + c * f.y);
    };
    // The spectrum's peak is located to within a bin: the fold searches no farther (a real photo's
    // fold, blurred and speckled, drifts to the search's end), and at most 3 %.
    const double reach = std::min(0.03, 1.0 / (double(std::max(width, height)) * length));
    // Length and direction in turn: each barely moves the other's optimum.
    for (int pass = 0; pass < 2; ++pass) {
        scale = maximise([&](double s) { return profileVariance(values, width, height, frequency(s, angle)); },
                         1.0 - reach, 1.0 + reach, 30);
        const double halfAngle = 1.5 * M_PI / 180.0;
        angle = maximise([&](double a) { return profileVariance(values, width, height, frequency(scale, a)); },
                         -halfAngle, halfAngle, 15);
    }
    return frequency(scale, angle);
}

TileFold foldTile(const Image& image, const ThreadGrid& grid) {
    return image.pixels.empty() ? TileFold{} : foldAtPhase(image, grid, foldPhase(image, grid));
}

std::vector<TileFold> foldsLaidOn(const TileFold& photo, const Image& reference, const std::vector<const Image*>& images,
                                  const ThreadGrid& grid) {
    const glm::dvec2 phase = foldPhase(reference, grid);
    const FoldShift shift = alignFolds(photo, foldAtPhase(reference, grid, phase));
    std::vector<TileFold> folds;
    for (const Image* image : images) {
        const TileFold f = foldAtPhase(*image, grid, phase);
        TileFold laid = f;
        for (int v = 0; v < f.side; ++v)
            for (int u = 0; u < f.side; ++u) {
                const size_t b = size_t(v) * size_t(f.side) + size_t(u), from = shiftedBin(f, u, v, shift);
                laid.mean[b] = f.mean[from];
                laid.weight[b] = f.weight[from];
            }
        folds.push_back(std::move(laid));
    }
    return folds;
}

std::vector<size_t> sharedBins(const TileFold& photo, const TileFold& laid) {
    std::vector<size_t> bins;
    if (photo.side == 0 || laid.side != photo.side) return bins;
    for (size_t b = 0; b < photo.mean.size(); ++b)
        if (photo.weight[b] > 0.0f && laid.weight[b] > 0.0f) bins.push_back(b);
    return bins;
}

double foldError(const TileFold& photo, const TileFold& render) {
    if (photo.side == 0 || photo.side != render.side) return 0.0;
    const int n = photo.side;
    const FoldShift shift = alignFolds(photo, render);
    const glm::dvec3 scale = foldChannelMeans(photo);
    double e = 0.0;
    int count = 0;
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const size_t p = size_t(v) * size_t(n) + size_t(u), r = shiftedBin(render, u, v, shift);
            if (photo.weight[p] <= 0.0f || render.weight[r] <= 0.0f) continue;
            const glm::dvec3 d = (glm::dvec3(render.mean[r]) - glm::dvec3(photo.mean[p])) / scale;
            e += glm::dot(d, d);
            count += 3;
        }
    return count > 0 ? e / count : 0.0;
}

}  // namespace woven
