#include "denoiser.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "albedo_demodulation.h"
#include "fast_math.h"
#include "padded_planes.h"

namespace woven {

namespace {

// Rows filtered together: the patch distances of a tile's rows need f rows above and below, so a
// taller tile wastes less on them, a shorter one shares the frame out more evenly.
constexpr int kTileRows = 32;
// eps in D_c: keeps 0 / 0 (two noise-free pixels) finite; their difference then decides alone.
constexpr float kEpsilon = 1e-10f;

// Adds the weights exp(-dist[i]) of neighbours q = p + offset (0 for unusable ones) and their
// weighted differences to p, for count pixels p of a row. __restrict: nothing here overlaps, and
// without it the compiler would not vectorise the loop.
void accumulate(int count, const float* __restrict dist, const float* __restrict usable, const float* __restrict u0,
                const float* __restrict u1, const float* __restrict u2, ptrdiff_t offset, float* __restrict weights,
                float* __restrict s0, float* __restrict s1, float* __restrict s2) {
    for (int i = 0; i < count; ++i) {
        const float weight = usable[i] * fastExpInRange(-dist[i]);
        weights[i] += weight;
        s0[i] += weight * (u0[i + offset] - u0[i]);
        s1[i] += weight * (u1[i + offset] - u1[i]);
        s2[i] += weight * (u2[i + offset] - u2[i]);
    }
}

struct Planes {
    PaddedPlanes irradiance, variance, divisor, usable;
};

class Filter {
public:
    Filter(const DenoiseBuffers& b, const DenoiseSettings& s)
        : b_(b), s_(s), pad_(s.radius + s.patchRadius), guide_(b, s.features, pad_) {
        const Demodulated d = demodulate(b);
        auto planes = [&](const Planes3& p) {
            return PaddedPlanes(b.width, b.height, 3, pad_, [&](size_t i, int c) { return p.c[size_t(c)][i]; });
        };
        planes_.irradiance = planes(d.irradiance);
        planes_.variance = planes(d.variance);
        planes_.divisor = planes(d.divisor);
        planes_.usable = PaddedPlanes(b.width, b.height, 1, pad_, [&](size_t i, int) { return b.usable(i) ? 1.0f : 0.0f; });
    }

    void rows(int y0, int y1, std::vector<glm::vec3>& out) const;

private:
    const DenoiseBuffers& b_;
    const DenoiseSettings& s_;
    int pad_;
    FeatureGuide guide_;
    Planes planes_;
};

void Filter::rows(int y0, int y1, std::vector<glm::vec3>& out) const {
    const int w = b_.width, h = b_.height, f = s_.patchRadius, r = s_.radius;
    const int tile = y1 - y0, patchRows = tile + 2 * f, patchCols = w + 2 * f;
    const float k2 = s_.k * s_.k, alpha = s_.alpha, patchNorm = 1.0f / float((2 * f + 1) * (2 * f + 1) * 3);
    const ptrdiff_t stride = planes_.irradiance.stride();
    std::vector<float> distance(size_t(patchRows) * patchCols), horizontal(size_t(patchRows) * w), patch(w), features(w);
    std::vector<float> weights(size_t(tile) * w, 1.0f);  // the centre's own weight
    std::vector<float> sums[3];
    for (auto& sum : sums) sum.assign(size_t(tile) * w, 0.0f);
    const float* u[3] = {planes_.irradiance.plane(0), planes_.irradiance.plane(1), planes_.irradiance.plane(2)};
    const float* v[3] = {planes_.variance.plane(0), planes_.variance.plane(1), planes_.variance.plane(2)};
    const float* usable = planes_.usable.plane(0);

    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const ptrdiff_t offset = dy * stride + dx;
            // D_c's terms at every pixel of the patches, the frame's edge repeated beyond it.
            for (int j = 0; j < patchRows; ++j) {
                const size_t p = planes_.irradiance.index(-f, y0 - f + j);
                float* d = &distance[size_t(j) * patchCols];
                std::fill(d, d + patchCols, 0.0f);
                for (int c = 0; c < 3; ++c) {
                    const float* uc = u[c] + p;
                    const float* vc = v[c] + p;
                    for (int i = 0; i < patchCols; ++i) {
                        const float vp = vc[i], vq = vc[i + offset], diff = uc[i] - uc[i + offset];
                        d[i] += (diff * diff - alpha * (vp + std::min(vp, vq))) / (kEpsilon + k2 * (vp + vq));
                    }
                }
                float* hz = &horizontal[size_t(j) * w];
                for (int x = 0; x < w; ++x) {
                    float sum = 0.0f;
                    for (int t = 0; t <= 2 * f; ++t) sum += d[x + t];
                    hz[x] = sum;
                }
            }
            // Only neighbours inside the frame are averaged in.
            const int x0 = std::max(0, -dx), x1 = std::min(w, w - dx);
            for (int t = 0; t < tile; ++t) {
                const int y = y0 + t;
                if (y + dy < 0 || y + dy >= h || x1 <= x0) continue;
                const size_t p = planes_.irradiance.index(x0, y);
                const int count = x1 - x0;
                // The patch distance, then the weight, each in a loop of its own that vectorises.
                float* const dist = patch.data();
                std::fill(dist, dist + count, 0.0f);
                for (int j = 0; j <= 2 * f; ++j) {
                    const float* hz = &horizontal[size_t(t + j) * w + x0];
                    for (int i = 0; i < count; ++i) dist[i] += hz[i];
                }
                guide_.distances(p, offset, count, features.data());
                for (int i = 0; i < count; ++i)
                    dist[i] = std::min(80.0f, std::max(std::max(0.0f, dist[i] * patchNorm), features[size_t(i)]));
                const size_t a = size_t(t) * w + x0;
                accumulate(count, dist, usable + p + offset, u[0] + p, u[1] + p, u[2] + p, offset, &weights[a], &sums[0][a],
                           &sums[1][a], &sums[2][a]);
            }
        }
    // The colour plus the weighted mean of the neighbours' differences, remodulated: a pixel
    // whose neighbours all equal it is returned exactly.
    const float* divisor[3] = {planes_.divisor.plane(0), planes_.divisor.plane(1), planes_.divisor.plane(2)};
    for (int t = 0; t < tile; ++t)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y0 + t) * w + x, p = planes_.irradiance.index(x, y0 + t), a = size_t(t) * w + x;
            glm::vec3 c = b_.color[i];
            if (usable[p] != 0.0f)
                for (int ch = 0; ch < 3; ++ch) c[ch] += divisor[ch][p] * sums[ch][a] / weights[a];
            out[i] = c;
        }
}

}  // namespace

DenoiseResult denoise(const DenoiseBuffers& buffers, const DenoiseSettings& settings) {
    checkDenoiseBuffers(buffers);
    if (settings.radius < 1 || settings.patchRadius < 0 || !(settings.k > 0.0f) || !(settings.alpha >= 0.0f))
        throw std::invalid_argument("denoise: radius must be at least 1, patch radius at least 0, k above 0 and alpha at least 0");
    const Filter filter(buffers, settings);
    DenoiseResult result;
    result.color.resize(buffers.pixels());
    const int tiles = (buffers.height + kTileRows - 1) / kTileRows;
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& range) {
        for (int t = range.begin(); t != range.end(); ++t)
            filter.rows(t * kTileRows, std::min(buffers.height, (t + 1) * kTileRows), result.color);
    });
    for (size_t i = 0; i < buffers.pixels(); ++i) result.unusablePixels += buffers.usable(i) ? 0 : 1;
    return result;
}

}  // namespace woven
