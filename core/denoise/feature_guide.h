#pragma once
// How alike two pixels' render passes are: the feature term of Rousselle, Manzi and Zwicker 2013
// ("Robust denoising using feature and color information"). For each pass k (albedo, normal,
// depth) the distance of pixel q to pixel p is
//     Phi_k^2(p, q) = |f_k(p) - f_k(q)|^2 / (k_f^2 max(tau_k, g |grad f_k(p)|^2)),
// and the pair's feature distance is the largest over the passes: one pass that tells them apart
// (a thread of another colour, a yarn bent the other way, a silhouette) is enough. The gradient
// term is the paper's: across an edge a feature varies by about its gradient from one pixel to
// the next, and the passes are averages over each pixel's footprint, so an edge pixel holds a mix
// that a strict tau would set apart from both sides. The passes carry no variance of their own
// here (Rousselle et al. take it off Phi^2): they are nearly noise-free where the camera ray's
// first hit is sharp, and tau stands in for what noise they have.
#include <cstddef>
#include <vector>

#include "denoise_buffers.h"
#include "padded_planes.h"

namespace woven {

struct FeatureSettings {
    float k = 0.6f;              // k_f, the paper's
    float tauAlbedo = 1e-3f;     // squared reflectance difference
    float tauNormal = 1e-2f;     // squared unit-vector difference (about 5.7 degrees)
    float tauDepth = 1e-4f;      // squared difference of ln(depth): 1 % of the distance
    // g: the paper's 1 lets a pixel on a yarn take neighbours across the next yarn's edge, where
    // the normal turns within a pixel, and blurs the satin's floats (their fine detail kept 64 %
    // of the reference's at 320 x 240); at 0.3 it keeps 83 % and the relMSE is lower (tuned on
    // the paper's satin, docs/RESULTS.md).
    float gradientScale = 0.3f;
};

class FeatureGuide {
public:
    // The planes padded by `pad` pixels (PaddedPlanes), so that distance() takes any neighbour
    // within pad of the frame.
    FeatureGuide(const DenoiseBuffers& buffers, const FeatureSettings& settings, int pad);

    // out[i] = max_k Phi_k^2(p + i, p + i + offset) for padded indices p + i, i < count; 0 with
    // no passes.
    void distances(size_t p, ptrdiff_t offset, int count, float* out) const;

private:
    struct Feature {
        PaddedPlanes planes;
        PaddedPlanes inverseScale;  // 1 / (k_f^2 max(tau, g |grad|^2)), one plane
    };
    std::vector<Feature> features_;
};

}  // namespace woven
