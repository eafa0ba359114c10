#include "transmitted_colours.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "fit_loss.h"
#include "yarn_transmission.h"

namespace woven {

namespace {

// The colours' range, as stage 4's axes have it (fabric_fit.cpp).
constexpr double kLeastColour = 0.002, kMostColour = 1.0;
// BOBYQA's evaluations: each costs some hundred multiplications, no render; enough for 8 unknowns
// to converge (2n + 1 = 17 set up its model).
constexpr int kEvaluations = 800;
// How far from the reflected solve's a free exposure is searched, as a factor either way.
constexpr double kExposureRange = 4.0;
// How far rs's factor is searched, either way, as the exposure: the reflected shots' renders are
// at the shot material's rs (0.04 by default) or at the best fit's.
constexpr double kRsRange = 4.0;

// Each backlit residual at the colours, as (d, g, rhs, weight): the render's statistic over the
// photo's scale of its channel is T_d d + T_g g, the photo's rhs.
template <class Residual>
void forEachBacklitResidual(const std::vector<const ImageStats*>& photos, const std::vector<TransmissionStats>& parts,
                            const std::vector<double>& exposures, const glm::dvec3& weft, const glm::dvec3& warp,
                            const Residual& residual) {
    const std::array<glm::dvec3, kTransmittedRegionCount> tau = regionTransmittances(weft, warp);
    const double blockWeight = lossWeights()[kStatBlockMeans], foldWeight = lossWeights()[kStatTileFold];
    for (size_t s = 0; s < photos.size(); ++s) {
        const TransmissionStats& p = parts[s];
        const double e = exposures[s];
        const std::vector<float>& pm = photos[s]->values[kStatBlockMeans];
        const glm::dvec3 scale = channelMeans(pm, 1);
        for (size_t i = 0; i < pm.size(); ++i) {
            const int c = int(i % 3);
            double d = 0.0, g = 0.0;
            for (int r = 0; r < kTransmittedRegionCount; ++r) {
                d += tau[size_t(r)][c] * p.blockMeans[size_t(r)][i];
                g += tau[size_t(r)][c] * p.blockMeans[size_t(kTransmittedRegionCount + r)][i];
            }
            residual(e * d / scale[c], e * g / scale[c], pm[i] / scale[c], blockWeight / double(pm.size()));
        }
        const TileFold& pf = photos[s]->fold;
        const std::vector<size_t> bins = sharedBins(pf, p.folds[0]);
        if (bins.empty()) continue;
        const glm::dvec3 foldScale = foldChannelMeans(pf);
        for (size_t b : bins)
            for (int c = 0; c < 3; ++c) {
                double d = 0.0, g = 0.0;
                for (int r = 0; r < kTransmittedRegionCount; ++r) {
                    d += tau[size_t(r)][c] * p.folds[size_t(r)].mean[b][c];
                    g += tau[size_t(r)][c] * p.folds[size_t(kTransmittedRegionCount + r)].mean[b][c];
                }
                residual(e * d / foldScale[c], e * g / foldScale[c], pf.mean[b][c] / foldScale[c],
                         foldWeight / double(3 * bins.size()));
            }
    }
}

double backlitResidual(const std::vector<const ImageStats*>& photos, const std::vector<TransmissionStats>& parts,
                       const std::vector<double>& exposures, const glm::dvec3& weft, const glm::dvec3& warp,
                       const TransmissionSplit& split) {
    double sum = 0.0;
    forEachBacklitResidual(photos, parts, exposures, weft, warp, [&](double d, double g, double rhs, double weight) {
        const double r = split.diffuse * d + split.glossy * g - rhs;
        sum += weight * r * r;
    });
    return sum;
}

double trampoline(const std::vector<double>& x, std::vector<double>&, void* data) {
    return (*static_cast<const std::function<double(const std::vector<double>&)>*>(data))(x);
}

}  // namespace

std::array<glm::dvec3, kTransmittedRegionCount> regionTransmittances(const glm::dvec3& weft, const glm::dvec3& warp) {
    const glm::dvec3 w(yarnTransmittance(glm::vec3(weft), 1.0f)), p(yarnTransmittance(glm::vec3(warp), 1.0f));
    return {w, p, glm::min(w, p)};
}

TransmissionSplit solveTransmission(const std::vector<const ImageStats*>& photos,
                                    const std::vector<TransmissionStats>& parts, const std::vector<double>& exposures,
                                    const glm::dvec3& weft, const glm::dvec3& warp) {
    glm::dmat2 A(0.0);
    glm::dvec2 y(0.0);
    forEachBacklitResidual(photos, parts, exposures, weft, warp, [&](double d, double g, double rhs, double weight) {
        const glm::dvec2 x(d, g);
        A += weight * glm::outerProduct(x, x);
        y += weight * x * rhs;
    });
    // The unconstrained minimum, else the better of the two edges (one part alone).
    glm::dvec2 ab(0.0);
    if (std::abs(glm::determinant(A)) > 1e-12 * (A[0][0] * A[1][1] + 1e-300)) ab = glm::inverse(A) * y;
    if (!(ab.x >= 0.0 && ab.y >= 0.0)) {
        const glm::dvec2 onlyD(A[0][0] > 0.0 ? std::max(0.0, y.x / A[0][0]) : 0.0, 0.0);
        const glm::dvec2 onlyG(0.0, A[1][1] > 0.0 ? std::max(0.0, y.y / A[1][1]) : 0.0);
        const auto cost = [&](const glm::dvec2& v) { return glm::dot(v, A * v) - 2.0 * glm::dot(v, y); };
        ab = cost(onlyD) <= cost(onlyG) ? onlyD : onlyG;
    }
    // t is at most 1: scaled back along the same split where the photos ask for more.
    const double t = ab.x + ab.y;
    if (t > 1.0) ab /= t;
    return {ab.x, ab.y};
}

TransmittedColours solveColoursWithTransmission(const std::vector<const ImageStats*>& reflectedPhotos,
                                                const std::vector<LinearStats>& reflected,
                                                const std::vector<std::optional<double>>& reflectedExposures,
                                                const std::vector<const ImageStats*>& backlitPhotos,
                                                const std::vector<TransmissionStats>& backlit,
                                                const std::vector<std::optional<double>>& backlitExposures,
                                                const std::vector<LinearColours>& starts, bool solveRs) {
    const bool free = !reflectedExposures.empty() && !reflectedExposures[0];
    const bool rsFree = free && solveRs;
    const auto backlitExposuresAt = [&](double exposure) {
        std::vector<double> e;
        for (const std::optional<double>& b : backlitExposures) e.push_back(b.value_or(free ? exposure : 1.0));
        return e;
    };
    const auto objective = [&](const glm::dvec3& weft, const glm::dvec3& warp, double exposure, double rsScale) {
        const std::vector<double> e = backlitExposuresAt(exposure);
        const TransmissionSplit split = solveTransmission(backlitPhotos, backlit, e, weft, warp);
        return colourResidual(reflectedPhotos, reflected, reflectedExposures, weft, warp, exposure, rsScale) +
               backlitResidual(backlitPhotos, backlit, e, weft, warp, split);
    };
    TransmittedColours best;
    double bestValue = INFINITY;
    for (const LinearColours& start : starts) {
        // x: the six colours on [kLeastColour, kMostColour], then a free exposure and rs's factor,
        // each a power of its range about the start's (the factor's about 1).
        const auto colour = [](double u) { return kLeastColour + std::clamp(u, 0.0, 1.0) * (kMostColour - kLeastColour); };
        const auto unit = [](double c) { return std::clamp((c - kLeastColour) / (kMostColour - kLeastColour), 0.0, 1.0); };
        const auto exposure = [&](const std::vector<double>& x) {
            return free ? start.exposure * std::pow(kExposureRange, 2.0 * std::clamp(x[6], 0.0, 1.0) - 1.0) : start.exposure;
        };
        const auto rsScale = [&](const std::vector<double>& x) {
            return rsFree ? std::pow(kRsRange, 2.0 * std::clamp(x[7], 0.0, 1.0) - 1.0) : 1.0;
        };
        const std::function<double(const std::vector<double>&)> f = [&](const std::vector<double>& x) {
            return objective({colour(x[0]), colour(x[1]), colour(x[2])}, {colour(x[3]), colour(x[4]), colour(x[5])},
                             exposure(x), rsScale(x));
        };
        std::vector<double> x{unit(start.weft.r), unit(start.weft.g), unit(start.weft.b),
                              unit(start.warp.r), unit(start.warp.g), unit(start.warp.b)};
        if (free) x.push_back(0.5);
        if (rsFree) x.push_back(0.5);
        nlopt::opt opt(nlopt::LN_BOBYQA, unsigned(x.size()));
        opt.set_lower_bounds(std::vector<double>(x.size(), 0.0));
        opt.set_upper_bounds(std::vector<double>(x.size(), 1.0));
        opt.set_min_objective(trampoline, const_cast<std::function<double(const std::vector<double>&)>*>(&f));
        opt.set_maxeval(kEvaluations);
        opt.set_initial_step(0.05);
        opt.set_xtol_rel(1e-6);
        double value = 0.0;
        try {
            opt.optimize(x, value);
        } catch (const std::runtime_error&) {
            // roundoff_limited: x holds the best point met.
        }
        value = f(x);
        if (!(value < bestValue)) continue;
        bestValue = value;
        best.colours.weft = {colour(x[0]), colour(x[1]), colour(x[2])};
        best.colours.warp = {colour(x[3]), colour(x[4]), colour(x[5])};
        best.colours.exposure = exposure(x);
        best.rsScale = rsScale(x);
        best.colours.valid = true;
        best.split = solveTransmission(backlitPhotos, backlit, backlitExposuresAt(best.colours.exposure), best.colours.weft,
                                       best.colours.warp);
    }
    return best;
}

}  // namespace woven
