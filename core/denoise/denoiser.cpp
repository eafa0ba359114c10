#include "denoiser.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <optional>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "albedo_demodulation.h"
#include "fast_math.h"
#include "feature_regression.h"
#include "padded_planes.h"
#include "sure_selection.h"
#include "vector_clones.h"

namespace woven {

namespace {

// Pixels filtered together: the patch distances of a tile need f pixels around it, so a larger
// tile wastes less on them, a smaller one shares the frame out more evenly and keeps its sums
// (eight floats a pixel per candidate) in the core's cache, which whole rows of a 1280-pixel
// frame, 32 at a time, overflowed (2.6 MB for two candidates).
constexpr int kTileRows = 32, kTileColumns = 256;
// eps in D_c: keeps 0 / 0 (two noise-free pixels) finite; their difference then decides alone.
constexpr float kEpsilon = 1e-10f;

// One candidate filter's sums over the window, per pixel of a tile: the weights w_q (the centre's
// own 1 included), the weighted differences w_q (u_q - u_p), and what SURE needs of how the
// weights move with p's own colour (sure_selection.h): per channel the sum of w_q s_q, s_q the
// slope of q's weight distance in u_p, and over channels the sum of w_q Var_p s_q (u_q - u_p).
struct CandidateSums {
    std::vector<float> weight, varianceSlopeDifference;
    std::array<std::vector<float>, 3> difference, slope;
    explicit CandidateSums(size_t n) : weight(n, 1.0f), varianceSlopeDifference(n, 0.0f) {
        for (int c = 0; c < 3; ++c) {
            difference[size_t(c)].assign(n, 0.0f);
            slope[size_t(c)].assign(n, 0.0f);
        }
    }
};

// What the candidates share of one row of neighbours q = p + offset: per channel the slope s of
// D_c (k_c^2 left out) in u_p, and over channels Var_p s (u_q - u_p), Var_p the radiance's.
struct RowTerms {
    std::array<std::vector<float>, 3> slope;
    std::vector<float> varianceSlopeDifference;
    explicit RowTerms(size_t n) : varianceSlopeDifference(n) {
        for (auto& plane : slope) plane.resize(n);
    }
};

// One channel's part of accumulate() below.
inline __attribute__((always_inline)) void addChannel(int count, const float* __restrict weight, const float* __restrict weightedGain,
                const float* __restrict u, ptrdiff_t offset, const float* __restrict slope, float* __restrict d,
                float* __restrict sl) {
    for (int i = 0; i < count; ++i) {
        d[i] += weight[i] * (u[i + offset] - u[i]);
        sl[i] += weightedGain[i] * slope[i];
    }
}

// Adds the weights exp(-dist[i]) of count neighbours q = p + offset (0 for unusable ones), their
// weighted differences and slope sums to one candidate's sums from index a; gain[i]: 1 / k_c^2
// where the colour term decides the weight, else 0; weight, weightedGain: scratch for count
// floats. __restrict: nothing here overlaps, and without it the compiler would not vectorise the
// loops.
inline __attribute__((always_inline)) void accumulate(int count, const float* __restrict dist, const float* __restrict gain, const float* __restrict usable,
                const float* const* u, ptrdiff_t offset, const RowTerms& row, CandidateSums& sums, size_t a,
                float* __restrict weight, float* __restrict weightedGain) {
    float* __restrict weights = &sums.weight[a];
    float* __restrict vsd = &sums.varianceSlopeDifference[a];
    const float* __restrict rowVsd = row.varianceSlopeDifference.data();
    for (int i = 0; i < count; ++i) {
        weight[i] = usable[i] * fastExpInRange(-dist[i]);
        weights[i] += weight[i];
        weightedGain[i] = weight[i] * gain[i];
        vsd[i] += weightedGain[i] * rowVsd[i];
    }
    for (int c = 0; c < 3; ++c)
        addChannel(count, weight, weightedGain, u[c], offset, row.slope[size_t(c)].data(), &sums.difference[size_t(c)][a],
                   &sums.slope[size_t(c)][a]);
}

// w[i] = exp(-dist[i]), 0 for unusable neighbours: the regression's weights.
inline __attribute__((always_inline)) void weights(int count, const float* __restrict dist, const float* __restrict usable,
                                                   float* __restrict w) {
    for (int i = 0; i < count; ++i) w[i] = usable[i] * fastExpInRange(-dist[i]);
}

// Each candidate filter's denoised frame and its per-pixel SURE, what sure_selection.h picks from.
struct Candidates {
    std::vector<std::vector<glm::vec3>> color;
    std::vector<std::vector<float>> risk;
};

struct Planes {
    PaddedPlanes irradiance, variance, divisor, usable;
};

// The pixels xa <= x < xb of rows y0 <= y < y1, filtered together, and what Filter::tile gathers
// for them over the window's neighbours.
struct Tile {
    int xa, y0, xb, y1;
    int th, tw, patchRows, patchCols;  // the tile's size, and its patches' pixels' (f beyond it)
    float patchNorm;                   // 1 / the count of a patch's terms: D_c is their mean
    // The planes' first floats: u the irradiance, v its variance, the albedo divisors, and 1 or 0
    // where the pixel is usable or not.
    const float *u[3], *v[3], *divisor[3], *usable;
    // Per row of the patches' pixels, D_c's terms with k_c^2 left out, and their sums over the
    // width of a patch.
    std::vector<float> distance, horizontal;
    // Per channel over the patches' pixels, (u_p - u_q) / (eps + Var_p + Var_q): half the slope of
    // each pixel's term of D_c in u_p.
    std::array<std::vector<float>, 3> halfSlope;
    // Of one row of the tile: the patch distances, the feature distances, one candidate's weight
    // distances, the terms the candidates share, and accumulate()'s gains and scratch.
    std::vector<float> patch, features, candidateDistance;
    RowTerms row;
    std::vector<float> gain, weightScratch, weightedGain;
    std::vector<CandidateSums> sums;               // each candidate filter's
    std::optional<FeatureRegression::Sums> fitSums;  // the regression's, where it is a candidate

    Tile(int xa_, int y0_, int xb_, int y1_, int f, const Planes& planes, size_t candidates, bool regression)
        : xa(xa_), y0(y0_), xb(xb_), y1(y1_), th(y1 - y0), tw(xb - xa), patchRows(th + 2 * f), patchCols(tw + 2 * f),
          patchNorm(1.0f / float((2 * f + 1) * (2 * f + 1) * 3)),
          u{planes.irradiance.plane(0), planes.irradiance.plane(1), planes.irradiance.plane(2)},
          v{planes.variance.plane(0), planes.variance.plane(1), planes.variance.plane(2)},
          divisor{planes.divisor.plane(0), planes.divisor.plane(1), planes.divisor.plane(2)},
          usable(planes.usable.plane(0)), distance(size_t(patchRows) * patchCols), horizontal(size_t(patchRows) * tw),
          patch(tw), features(tw), candidateDistance(tw), row(static_cast<size_t>(tw)), gain(static_cast<size_t>(tw)),
          weightScratch(static_cast<size_t>(tw)), weightedGain(static_cast<size_t>(tw)),
          sums(candidates, CandidateSums(size_t(th) * tw)) {
        for (auto& plane : halfSlope) plane.resize(distance.size());
        if (regression) fitSums.emplace(size_t(th) * tw);
    }
};

// One row of a tile against the neighbours q = p + offset inside the frame: count pixels from
// frame pixel x0 of the tile's row t, at padded index p and index a of the tile's sums.
struct RowSpan {
    int t, x0, count;
    size_t p, a;
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
        if (s.regression && FeatureRegression::applies(b)) regression_.emplace(b, d, pad_);
    }

    // The candidates' count: the filters', and the regression's where the frame has its pass.
    size_t candidates() const { return s_.candidateK.size() + (regression_ ? 1 : 0); }

    // Filters the pixels xa <= x < xb of rows y0 <= y < y1 with every candidate.
    void tile(int xa, int y0, int xb, int y1, Candidates& out) const;

private:
    // The steps of tile(), in its order. Each is inlined into tile()'s clones (vector_clones.h)
    // so that its arithmetic is compiled, FMA contractions included, as one function's: the
    // denoised frames stay the same to the bit.
    inline __attribute__((always_inline)) void patchTerms(Tile& tile, ptrdiff_t offset) const;
    inline __attribute__((always_inline)) void patchDistances(Tile& tile, const RowSpan& span) const;
    inline __attribute__((always_inline)) void rowTerms(Tile& tile, const RowSpan& span, int dx, int dy, ptrdiff_t offset) const;
    inline __attribute__((always_inline)) void addWeights(Tile& tile, const RowSpan& span, ptrdiff_t offset) const;
    inline __attribute__((always_inline)) void filtered(const Tile& tile, Candidates& out) const;
    inline __attribute__((always_inline)) void regressed(const Tile& tile, Candidates& out) const;

    const DenoiseBuffers& b_;
    const DenoiseSettings& s_;
    int pad_;
    FeatureGuide guide_;
    Planes planes_;
    std::optional<FeatureRegression> regression_;
};

// D_c's terms at every pixel of the tile's patches against q = p + offset, the frame's edge
// repeated beyond it, with k_c^2 left out (the candidates differ only in it and share the rest),
// their half slopes, and their sums over a patch's width.
void Filter::patchTerms(Tile& tile, ptrdiff_t offset) const {
    const int f = s_.patchRadius, tw = tile.tw, patchCols = tile.patchCols;
    const float alpha = s_.alpha;
    for (int j = 0; j < tile.patchRows; ++j) {
        const size_t p = planes_.irradiance.index(tile.xa - f, tile.y0 - f + j);
        float* d = &tile.distance[size_t(j) * patchCols];
        std::fill(d, d + patchCols, 0.0f);
        for (int c = 0; c < 3; ++c) {
            const float* uc = tile.u[c] + p;
            const float* vc = tile.v[c] + p;
            float* hs = &tile.halfSlope[size_t(c)][size_t(j) * patchCols];
            for (int i = 0; i < patchCols; ++i) {
                const float vp = vc[i], vq = vc[i + offset], diff = uc[i] - uc[i + offset];
                const float inverse = 1.0f / (kEpsilon + vp + vq);
                d[i] += (diff * diff - alpha * (vp + std::min(vp, vq))) * inverse;
                hs[i] = diff * inverse;
            }
        }
        // Column by column of the patch, each a loop over the row that vectorises (the
        // same additions in the same order as a sum per pixel).
        float* hz = &tile.horizontal[size_t(j) * tw];
        std::fill(hz, hz + tw, 0.0f);
        for (int t = 0; t <= 2 * f; ++t)
            for (int x = 0; x < tw; ++x) hz[x] += d[x + t];
    }
}

// The patch distance of each pixel of the span (in tile.patch), in a loop that vectorises.
void Filter::patchDistances(Tile& tile, const RowSpan& span) const {
    const int f = s_.patchRadius, count = span.count;
    const float patchNorm = tile.patchNorm;
    float* const dist = tile.patch.data();
    std::fill(dist, dist + count, 0.0f);
    for (int j = 0; j <= 2 * f; ++j) {
        const float* hz = &tile.horizontal[size_t(span.t + j) * tile.tw + (span.x0 - tile.xa)];
        for (int i = 0; i < count; ++i) dist[i] += hz[i];
    }
    for (int i = 0; i < count; ++i) dist[i] = dist[i] * patchNorm;
}

// The slope of D_c (k_c^2 left out) in p's own colour, per channel, and what the candidates share
// of it (tile.row): p is the centre of its patch, and where q is within a patch of p, p is in q's
// patch too, at the place of p - (q - p) in p's, where the pair is (p - offset, p).
void Filter::rowTerms(Tile& tile, const RowSpan& span, int dx, int dy, ptrdiff_t offset) const {
    const int f = s_.patchRadius, count = span.count;
    const float patchNorm = tile.patchNorm;
    const bool inPatch = std::abs(dx) <= f && std::abs(dy) <= f;
    const size_t centre = size_t(span.t + f) * tile.patchCols + size_t(span.x0 - tile.xa + f);
    const ptrdiff_t mirrored = -ptrdiff_t(dy) * tile.patchCols - dx;
    float* const vsd = tile.row.varianceSlopeDifference.data();
    std::fill(vsd, vsd + count, 0.0f);
    for (int c = 0; c < 3; ++c) {
        const float* uc = tile.u[c] + span.p;
        const float* vc = tile.v[c] + span.p;
        const float* dc = tile.divisor[c] + span.p;
        const float* hs = &tile.halfSlope[size_t(c)][centre];
        float* slope = tile.row.slope[size_t(c)].data();
        for (int i = 0; i < count; ++i) slope[i] = 2.0f * patchNorm * hs[i];
        if (inPatch)
            for (int i = 0; i < count; ++i) slope[i] -= 2.0f * patchNorm * hs[i + mirrored];
        for (int i = 0; i < count; ++i) vsd[i] += dc[i] * dc[i] * vc[i] * slope[i] * (uc[i + offset] - uc[i]);
    }
}

// Each candidate's weights of the span's neighbours, from the patch and feature distances, added
// to its sums; the regression's too, where it is a candidate.
void Filter::addWeights(Tile& tile, const RowSpan& span, ptrdiff_t offset) const {
    const int count = span.count;
    const float* const dist = tile.patch.data();
    const float* const features = tile.features.data();
    const float* uRow[3] = {tile.u[0] + span.p, tile.u[1] + span.p, tile.u[2] + span.p};
    float* const weightDistance = tile.candidateDistance.data();
    for (size_t k = 0; k < s_.candidateK.size(); ++k) {
        const float inverseK2 = 1.0f / (s_.candidateK[k] * s_.candidateK[k]);
        for (int i = 0; i < count; ++i) {
            const float colour = dist[i] * inverseK2;
            weightDistance[i] = std::min(80.0f, std::max(std::max(0.0f, colour), features[size_t(i)]));
            // The colour term decides the weight, so the weight moves with p's colour.
            tile.gain[size_t(i)] = colour > 0.0f && colour >= features[size_t(i)] && colour < 80.0f ? inverseK2 : 0.0f;
        }
        accumulate(count, weightDistance, tile.gain.data(), tile.usable + span.p + offset, uRow, offset, tile.row, tile.sums[k],
                   span.a, tile.weightScratch.data(), tile.weightedGain.data());
    }
    if (regression_) {
        const float fitInverseK2 = 1.0f / (s_.regressionK * s_.regressionK);
        for (int i = 0; i < count; ++i)
            weightDistance[i] = std::min(80.0f, std::max(std::max(0.0f, dist[i] * fitInverseK2), features[size_t(i)]));
        weights(count, weightDistance, tile.usable + span.p + offset, tile.weightScratch.data());
        regression_->accumulate(span.p, offset, count, tile.weightScratch.data(), uRow, *tile.fitSums, span.a);
    }
}

// Each candidate filter's frame: the colour plus the weighted mean of the neighbours'
// differences, remodulated (a pixel whose neighbours all equal it is returned exactly), and its
// SURE.
void Filter::filtered(const Tile& tile, Candidates& out) const {
    const int w = b_.width, xa = tile.xa, xb = tile.xb, y0 = tile.y0, tw = tile.tw;
    const float *const *v = tile.v, *const *divisor = tile.divisor, *usable = tile.usable;
    for (size_t k = 0; k < s_.candidateK.size(); ++k)
        for (int t = 0; t < tile.th; ++t)
            for (int x = xa; x < xb; ++x) {
                const size_t i = size_t(y0 + t) * w + x, p = planes_.irradiance.index(x, y0 + t), a = size_t(t) * tw + (x - xa);
                glm::vec3 c = b_.color[i];
                float risk = 0.0f;
                const CandidateSums& sum = tile.sums[k];
                if (usable[p] != 0.0f) {
                    // F = u + D / W, D the weighted differences; with the weights w_q = exp(-d_q)
                    // moving with u, dF/du = (1 - sum w_q d'_q (u_q - u) + (F - u) sum w_q d'_q) / W
                    // (Van De Ville and Kocher 2009, for non-local means); the middle sum is
                    // gathered over channels with their variances as SURE takes it.
                    const float weight = sum.weight[a];
                    for (int ch = 0; ch < 3; ++ch) {
                        const float mean = sum.difference[size_t(ch)][a] / weight, change = divisor[ch][p] * mean;
                        const float variance = divisor[ch][p] * divisor[ch][p] * v[ch][p];
                        c[ch] += change;
                        risk += steinUnbiasedRisk(change, variance, (1.0f + mean * sum.slope[size_t(ch)][a]) / weight);
                    }
                    risk -= 2.0f * sum.varianceSlopeDifference[a] / weight;
                }
                out.color[k][i] = c;
                out.risk[k][i] = risk;
            }
}

// The regression's frame: its fit at each pixel, and SURE with the weights held fixed (the fit
// is linear in the irradiance, so its derivative is the centre's leverage).
void Filter::regressed(const Tile& tile, Candidates& out) const {
    const int w = b_.width, xa = tile.xa, xb = tile.xb, y0 = tile.y0, tw = tile.tw;
    const size_t candidates = s_.candidateK.size();
    const float *const *v = tile.v, *const *divisor = tile.divisor, *usable = tile.usable;
    for (int t = 0; t < tile.th; ++t)
        for (int x = xa; x < xb; ++x) {
            const size_t i = size_t(y0 + t) * w + x, p = planes_.irradiance.index(x, y0 + t), a = size_t(t) * tw + (x - xa);
            glm::vec3 c = b_.color[i];
            float risk = 0.0f;
            if (usable[p] != 0.0f) {
                const FeatureRegression::Fit fit = regression_->solve(*tile.fitSums, a, i, s_.regressionRidge);
                for (int ch = 0; ch < 3; ++ch) {
                    const float change = divisor[ch][p] * fit.change[ch];
                    c[ch] += change;
                    risk += steinUnbiasedRisk(change, divisor[ch][p] * divisor[ch][p] * v[ch][p], fit.leverage);
                }
            }
            out.color[candidates][i] = c;
            out.risk[candidates][i] = risk;
        }
}

WOVEN_VECTOR_CLONES void Filter::tile(int xa, int y0, int xb, int y1, Candidates& out) const {
    const int w = b_.width, h = b_.height, r = s_.radius;
    Tile tile(xa, y0, xb, y1, s_.patchRadius, planes_, s_.candidateK.size(), regression_.has_value());
    const ptrdiff_t stride = planes_.irradiance.stride();
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            if (dx == 0 && dy == 0) continue;
            const ptrdiff_t offset = dy * stride + dx;
            patchTerms(tile, offset);
            // Only neighbours inside the frame are averaged in.
            const int x0 = std::max(xa, -dx), x1 = std::min(xb, w - dx);
            for (int t = 0; t < tile.th; ++t) {
                const int y = y0 + t;
                if (y + dy < 0 || y + dy >= h || x1 <= x0) continue;
                const RowSpan span{t, x0, x1 - x0, planes_.irradiance.index(x0, y), size_t(t) * tile.tw + (x0 - xa)};
                patchDistances(tile, span);
                rowTerms(tile, span, dx, dy, offset);
                guide_.distances(span.p, offset, span.count, tile.features.data());
                addWeights(tile, span, offset);
            }
        }
    filtered(tile, out);
    if (regression_) regressed(tile, out);
}

}  // namespace

DenoiseResult denoise(const DenoiseBuffers& buffers, const DenoiseSettings& settings) {
    checkDenoiseBuffers(buffers);
    const bool everyKPositive = std::all_of(settings.candidateK.begin(), settings.candidateK.end(), [](float k) { return k > 0.0f; });
    if (settings.radius < 1 || settings.patchRadius < 0 || settings.candidateK.empty() || !everyKPositive ||
        !(settings.alpha >= 0.0f) || settings.selectionRadius < 0 || !(settings.regressionK > 0.0f) ||
        !(settings.regressionRidge > 0.0f))
        throw std::invalid_argument(
            "denoise: radius must be at least 1, patch radius at least 0, at least one candidate k, each above 0, alpha and "
            "the selection radius at least 0, the regression's k and ridge above 0");
    const Filter filter(buffers, settings);
    const size_t n = buffers.pixels(), candidates = filter.candidates();
    Candidates out{std::vector<std::vector<glm::vec3>>(candidates, std::vector<glm::vec3>(n)),
                   std::vector<std::vector<float>>(candidates, std::vector<float>(n))};
    const int rows = (buffers.height + kTileRows - 1) / kTileRows, columns = (buffers.width + kTileColumns - 1) / kTileColumns;
    tbb::parallel_for(tbb::blocked_range<int>(0, rows * columns, 1), [&](const tbb::blocked_range<int>& range) {
        for (int t = range.begin(); t != range.end(); ++t) {
            const int x0 = (t % columns) * kTileColumns, y0 = (t / columns) * kTileRows;
            filter.tile(x0, y0, std::min(buffers.width, x0 + kTileColumns), std::min(buffers.height, y0 + kTileRows), out);
        }
    });
    DenoiseResult result;
    result.color = selectBySure(buffers.width, buffers.height, out.color, out.risk, settings.selectionRadius);
    for (size_t i = 0; i < n; ++i)
        if (!buffers.usable(i)) {
            result.color[i] = buffers.color[i];
            ++result.unusablePixels;
        }
    return result;
}

}  // namespace woven
