#pragma once
// The denoiser's regression candidate: in each pixel's window, the irradiance fitted as a linear
// function of the features that vary with it from sample to sample, weighted least squares with
// non-local-means weights, the fit's value at the pixel the estimate (first-order regression, as
// Bitterli et al. 2016, "Nonlinearly weighted first-order regression for denoising Monte Carlo
// renderings", and Moon et al. 2014 do). Its features are the direct-light pass's channels
// (FirstHit::direct) with the albedo divided out: on cloth whose threads are finer than a pixel,
// which yarns a pixel's samples hit changes its shading from pixel to pixel, and the direct light
// of the same samples follows that where the albedo, normal and depth averages hardly do; a
// filter that averages neighbours cannot keep it, a fit to the direct light can. A ridge term
// (a fraction of each regressor's own weighted square) keeps the fit stable where the direct
// light's channels move together or not at all. The pass is a mean of the pixel's own samples, so
// it carries their noise of where in the pixel they fell, which the colour shares and which a fit
// evaluated at the pixel's own pass would keep (SURE cannot see it: it is in a regressor). So the
// fit is evaluated at the pass shrunk towards the window's weighted mean by its reliability,
// signal / (signal + noise) from the window's spread and the pass's own variance (a Wiener
// estimate of the pass, as NFOR prefilters its features by their variance). The depth as a fourth regressor (NFOR's) made
// the satin's error 1 % lower and the denim's 4 % higher at a third more of the fit's cost
// (docs/RESULTS.md, run 5).
#include <array>
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "albedo_demodulation.h"
#include "denoise_buffers.h"
#include "padded_planes.h"

namespace woven {

class FeatureRegression {
public:
    static constexpr int kRegressors = 3;  // the direct light's R, G, B
    // Per pixel: the sum of w; of w x_j; of w x_j x_k (j <= k); of w u_c; of w x_j u_c: x the
    // regressors and u the irradiance, each less the window's centre pixel's.
    static constexpr int kMoments = 1 + kRegressors + kRegressors * (kRegressors + 1) / 2 + 3 + 3 * kRegressors;

    // The weighted sums over the window of a tile's pixels, the centre's own counted.
    struct Sums {
        std::array<std::vector<float>, kMoments> moment;
        explicit Sums(size_t pixels);
    };

    // The fit at one pixel: the irradiance's change per channel, and its derivative in the
    // pixel's own irradiance (the weights held fixed), what SURE needs.
    struct Fit {
        glm::vec3 change{0.0f};
        float leverage = 1.0f;
    };

    // Whether a frame has what the regression needs: a direct-light pass, not 0 everywhere.
    static bool applies(const DenoiseBuffers& buffers);

    // The regressors of every pixel, padded as the irradiance is (PaddedPlanes), and the
    // variance of each pixel's.
    FeatureRegression(const DenoiseBuffers& buffers, const Demodulated& demodulated, int pad);

    // Adds the count neighbours q = p + offset of the padded pixels p + i, with weights
    // weight[i], to the sums from index a; u: the irradiance planes, at p.
    void accumulate(size_t p, ptrdiff_t offset, int count, const float* weight, const float* const* u, Sums& sums,
                    size_t a) const;

    // The weighted least-squares fit of the sums at index a, each regressor's square raised by
    // `ridge` times itself, at frame pixel `pixel` (its regressors' variance).
    Fit solve(const Sums& sums, size_t a, size_t pixel, float ridge) const;

private:
    PaddedPlanes regressors_;
    std::vector<glm::vec3> variance_;  // of each pixel's regressors
};

}  // namespace woven
