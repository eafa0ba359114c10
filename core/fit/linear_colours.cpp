#include "linear_colours.h"

#include <cmath>

#include "fit_loss.h"

namespace woven {

namespace {

constexpr int kMaxUnknowns = 7;  // e x weft, e x warp (per channel) and e

// The normal equations of a weighted least-squares problem, one residual at a time.
struct NormalEquations {
    int n = 0;
    std::array<std::array<double, kMaxUnknowns>, kMaxUnknowns> a{};
    std::array<double, kMaxUnknowns> b{};

    void add(const std::array<double, kMaxUnknowns>& row, double rhs, double weight) {
        for (int i = 0; i < n; ++i) {
            b[size_t(i)] += weight * row[size_t(i)] * rhs;
            for (int j = 0; j < n; ++j) a[size_t(i)][size_t(j)] += weight * row[size_t(i)] * row[size_t(j)];
        }
    }

    // Gaussian elimination with partial pivoting; none where a pivot vanishes.
    std::optional<std::array<double, kMaxUnknowns>> solve() const {
        auto m = a;
        auto x = b;
        for (int c = 0; c < n; ++c) {
            int pivot = c;
            for (int r = c + 1; r < n; ++r)
                if (std::abs(m[size_t(r)][size_t(c)]) > std::abs(m[size_t(pivot)][size_t(c)])) pivot = r;
            if (!(std::abs(m[size_t(pivot)][size_t(c)]) > 1e-300)) return std::nullopt;
            std::swap(m[size_t(c)], m[size_t(pivot)]);
            std::swap(x[size_t(c)], x[size_t(pivot)]);
            for (int r = c + 1; r < n; ++r) {
                const double f = m[size_t(r)][size_t(c)] / m[size_t(c)][size_t(c)];
                for (int k = c; k < n; ++k) m[size_t(r)][size_t(k)] -= f * m[size_t(c)][size_t(k)];
                x[size_t(r)] -= f * x[size_t(c)];
            }
        }
        for (int r = n - 1; r >= 0; --r) {
            for (int k = r + 1; k < n; ++k) x[size_t(r)] -= m[size_t(r)][size_t(k)] * x[size_t(k)];
            x[size_t(r)] /= m[size_t(r)][size_t(r)];
        }
        return x;
    }
};

// Each residual of the problem solveColours() solves, as (row, rhs, weight): row . x - rhs, x the
// unknowns (e x weft, e x warp and e where the exposure is free; else weft and warp), relative to
// the photo's scale of that channel.
template <class Residual>
void forEachResidual(const std::vector<const ImageStats*>& photos, const std::vector<LinearStats>& renders,
                     const std::vector<std::optional<double>>& exposures, const Residual& residual) {
    const bool free = !exposures.empty() && !exposures[0];
    // Channel c of a statistic whose parts are k = (K_weft, K_warp, R). Free: R's term is e R;
    // given: each term times the shot's exposure, R's on the right.
    auto add = [&](int c, const glm::dvec3& k, double photo, double scale, double weight, std::optional<double> exposure) {
        std::array<double, kMaxUnknowns> row{};
        const double e = exposure.value_or(1.0);
        row[size_t(c)] = e * k[0] / scale;
        row[size_t(3 + c)] = e * k[1] / scale;
        double rhs = photo / scale;
        if (free)
            row[6] = k[2] / scale;
        else
            rhs -= e * k[2] / scale;
        residual(row, rhs, weight);
    };
    const double blockWeight = lossWeights()[kStatBlockMeans], foldWeight = lossWeights()[kStatTileFold];
    for (size_t s = 0; s < photos.size(); ++s) {
        const std::vector<float>& pm = photos[s]->values[kStatBlockMeans];
        const LinearStats& r = renders[s];
        const glm::dvec3 scale = channelMeans(pm, 1);
        for (size_t i = 0; i < pm.size(); ++i) {
            const int c = int(i % 3);
            add(c, {r.blockMeans[0][i], r.blockMeans[1][i], r.blockMeans[2][i]}, pm[i], scale[c],
                blockWeight / double(pm.size()), exposures[s]);
        }
        const TileFold& pf = photos[s]->fold;
        const std::vector<size_t> bins = sharedBins(pf, r.folds[0]);
        if (bins.empty()) continue;
        const glm::dvec3 foldScale = foldChannelMeans(pf);
        for (size_t b : bins)
            for (int c = 0; c < 3; ++c)
                add(c, {r.folds[0].mean[b][c], r.folds[1].mean[b][c], r.folds[2].mean[b][c]}, pf.mean[b][c], foldScale[c],
                    foldWeight / double(3 * bins.size()), exposures[s]);
    }
}

}  // namespace

LinearColours solveColours(const std::vector<const ImageStats*>& photos, const std::vector<LinearStats>& renders,
                           const std::vector<std::optional<double>>& exposures) {
    const bool free = !exposures.empty() && !exposures[0];
    NormalEquations eq;
    eq.n = free ? 7 : 6;
    forEachResidual(photos, renders, exposures,
                    [&](const std::array<double, kMaxUnknowns>& row, double rhs, double weight) { eq.add(row, rhs, weight); });
    LinearColours out;
    const auto x = eq.solve();
    if (!x) return out;
    out.exposure = free ? (*x)[6] : 1.0;
    if (!(out.exposure > 0.0)) return out;
    out.weft = glm::dvec3((*x)[0], (*x)[1], (*x)[2]) / out.exposure;
    out.warp = glm::dvec3((*x)[3], (*x)[4], (*x)[5]) / out.exposure;
    out.valid = true;
    return out;
}

double colourResidual(const std::vector<const ImageStats*>& photos, const std::vector<LinearStats>& renders,
                      const std::vector<std::optional<double>>& exposures, const glm::dvec3& weft, const glm::dvec3& warp,
                      double exposure, double gloss) {
    const bool free = !exposures.empty() && !exposures[0];
    const double e = free ? exposure : 1.0;
    const std::array<double, kMaxUnknowns> x{e * weft.r, e * weft.g, e * weft.b, e * warp.r, e * warp.g, e * warp.b, e * gloss};
    double sum = 0.0;
    forEachResidual(photos, renders, exposures, [&](const std::array<double, kMaxUnknowns>& row, double rhs, double weight) {
        double d = -rhs;
        for (size_t i = 0; i < x.size(); ++i) d += row[i] * x[i];
        sum += weight * d * d;
    });
    return sum;
}

}  // namespace woven
