#pragma once
// The denoiser of final frames: non-local means guided by the render passes, after Rousselle,
// Knaus and Zwicker 2012 ("Adaptive rendering with non-local means filtering") and Rousselle,
// Manzi and Zwicker 2013 ("Robust denoising using feature and color information"). Each pixel p
// becomes the weighted mean of the pixels q in a (2r+1)^2 window around it, the weight
//     w(p, q) = exp(-max(0, D_c(p, q), D_f(p, q))),
// the smaller of the colour weight and the feature weight. D_c is the mean over the
// (2f+1)^2 patches around p and q and over channels of
//     ((u_p - u_q)^2 - alpha (Var_p + min(Var_p, Var_q))) / (eps + k^2 (Var_p + Var_q)),
// the squared difference less what the pixels' noise explains, in units of that noise; D_f is
// FeatureGuide's. What is filtered is the colour with the albedo divided out
// (albedo_demodulation.h), multiplied back after: the threads stay as sharp as the albedo pass.
// The filter is run with several k_c at once (they share the patch distances), beside them, where
// the frame has a direct-light pass, a first-order regression on it (feature_regression.h), and
// each pixel takes the one of least estimated error (sure_selection.h).
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "denoise_buffers.h"
#include "feature_guide.h"

namespace woven {

struct DenoiseSettings {
    // r: the window is 13 x 13 pixels. 15 x 15 took 2-3 % off the satin's error but its
    // second candidate put the denoiser past 10 % of the render (docs/RESULTS.md).
    int radius = 6;
    int patchRadius = 3;    // f: 7 x 7 patches, the papers'
    // k_c of each candidate filter, the strongest first, chosen among per pixel by SURE
    // (sure_selection.h): the papers' 0.45, and a stricter one that keeps shading no pass shows
    // (the satin's float highlights) where the papers' blurs it (docs/RESULTS.md).
    std::vector<float> candidateK = {0.45f, 0.1f};
    // The regression candidate's weights: non-local means at this k_c, looser than the filters',
    // as the fit, not the weights, keeps what the direct light tells apart. 1, 1.5, 2 and 2.5 took
    // the satin to 5.2, 4.6, 4.6 and 4.8e-4 at 10 s (docs/RESULTS.md, run 5).
    float regressionK = 1.5f;
    // Each regressor's weighted square is raised by this fraction of itself (ridge regression):
    // 1e-1 took the denim's error 5 % under 1e-2 and 1e-3, the satin's the same; 3e-1 blurred the
    // satin's floats (fine detail 94 %).
    float regressionRidge = 1e-1f;
    bool regression = true;  // off: the filters alone, even with a direct-light pass
    float alpha = 1.0f;     // variance cancellation, the 2012 paper's
    int selectionRadius = 2;  // SURE and the choice are averaged over 5 x 5 pixels
    FeatureSettings features{};
};

struct DenoiseResult {
    std::vector<glm::vec3> color;  // the denoised linear RGB, row-major
    size_t unusablePixels = 0;     // left as they were (DenoiseBuffers::usable)
};

// Multithreaded (TBB, in the caller's arena). Throws std::invalid_argument on buffers of the
// wrong size (checkDenoiseBuffers) or settings out of range.
DenoiseResult denoise(const DenoiseBuffers& buffers, const DenoiseSettings& settings = {});

}  // namespace woven
