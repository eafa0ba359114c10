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
    float k = 0.6f;  // k_f, the paper's
    // tau_k, wider than noise-free passes would need: the passes are means of a pixel's samples,
    // and where threads are finer than a pixel each sample's first hit is one yarn or another,
    // so at 30 spp a pixel's albedo and normal carry noise of their own that the paper takes off
    // with a variance the passes here do not keep. Stricter taus refused the neighbours of the
    // denim's bright samples in its dark indigo and left them (relMSE 3.0e-2 against 2.0e-2 at
    // 320 x 240 and 10 s; the satin 4.0e-3 against 3.8e-3; docs/RESULTS.md).
    float tauAlbedo = 3e-2f;  // squared reflectance difference: the albedo is divided out anyway
    float tauNormal = 4e-2f;  // squared unit-vector difference (about 11 degrees)
    float tauDepth = 1e-3f;   // squared difference of ln(depth): 3 % of the distance
    // g: the paper's 1 lets a pixel on a yarn take neighbours across the next yarn's edge, where
    // the normal turns within a pixel, and blurs the satin's floats (their fine detail kept 65 %
    // of the reference's against 75 % at 0.3).
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
