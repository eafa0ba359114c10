#include "feature_guide.h"

#include <algorithm>
#include <cmath>

#include "vector_clones.h"

namespace woven {

namespace {

// A miss (depth 0 or infinite) is at this ln(depth): alike all misses, unlike every surface.
constexpr float kMissLogDepth = 1e4f;
// No pass varies by this much between neighbours on a surface: not albedo or a unit normal (at
// most 2), nor ln(depth) (a factor e^100).
constexpr float kNoGradient = 100.0f;

// 1 / (k_f^2 max(tau, g |grad f|^2)) at each pixel, by central differences (one-sided at the
// frame's border).
std::vector<float> inverseScales(const std::vector<std::vector<float>>& planes, int width, int height, float tau,
                                 const FeatureSettings& s) {
    std::vector<float> inverse(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, width - 1);
            const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, height - 1);
            float gradient = 0.0f;
            for (const std::vector<float>& f : planes) {
                const float gx = (f[size_t(y) * width + x1] - f[size_t(y) * width + x0]) / float(std::max(x1 - x0, 1));
                const float gy = (f[size_t(y1) * width + x] - f[size_t(y0) * width + x]) / float(std::max(y1 - y0, 1));
                // A step to or from a miss's sentinel is no gradient of the surface.
                if (std::fabs(gx) < kNoGradient) gradient += gx * gx;
                if (std::fabs(gy) < kNoGradient) gradient += gy * gy;
            }
            inverse[size_t(y) * width + x] = 1.0f / (s.k * s.k * std::max(tau, s.gradientScale * gradient));
        }
    return inverse;
}

}  // namespace

FeatureGuide::FeatureGuide(const DenoiseBuffers& b, const FeatureSettings& s, int pad) {
    const size_t n = b.pixels();
    auto add = [&](const std::vector<std::vector<float>>& planes, float tau) {
        const std::vector<float> inverse = inverseScales(planes, b.width, b.height, tau, s);
        features_.push_back(
            {PaddedPlanes(b.width, b.height, int(planes.size()), pad, [&](size_t i, int c) { return planes[size_t(c)][i]; }),
             PaddedPlanes(b.width, b.height, 1, pad, [&](size_t i, int) { return inverse[i]; })});
    };
    auto planesOf = [n](const std::vector<glm::vec3>& v) {
        std::vector<std::vector<float>> planes(3, std::vector<float>(n));
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) planes[size_t(c)][i] = std::isfinite(v[i][c]) ? v[i][c] : 0.0f;
        return planes;
    };
    if (!b.albedo.empty()) add(planesOf(b.albedo), s.tauAlbedo);
    if (!b.normal.empty()) add(planesOf(b.normal), s.tauNormal);
    if (!b.depth.empty()) {
        std::vector<std::vector<float>> planes(1, std::vector<float>(n));
        for (size_t i = 0; i < n; ++i) {
            const float d = b.depth[i];
            planes[0][i] = d > 0.0f && std::isfinite(d) ? std::log(d) : kMissLogDepth;
        }
        add(planes, s.tauDepth);
    }
}

WOVEN_VECTOR_CLONES void FeatureGuide::distances(size_t p, ptrdiff_t offset, int count, float* out) const {
    std::fill(out, out + count, 0.0f);
    for (const Feature& f : features_) {
        const float* scale = f.inverseScale.plane(0) + p;
        float* const o = out;  // the running maximum over the features
        const int channels = f.planes.channels();
        const float* c0 = f.planes.plane(0) + p;
        if (channels == 1) {
            for (int i = 0; i < count; ++i) {
                const float d = c0[i] - c0[i + offset];
                o[i] = std::max(o[i], d * d * scale[i]);
            }
            continue;
        }
        const float* c1 = f.planes.plane(1) + p;
        const float* c2 = f.planes.plane(2) + p;
        for (int i = 0; i < count; ++i) {
            const float d0 = c0[i] - c0[i + offset], d1 = c1[i] - c1[i + offset], d2 = c2[i] - c2[i + offset];
            o[i] = std::max(o[i], (d0 * d0 + d1 * d1 + d2 * d2) * scale[i]);
        }
    }
}

}  // namespace woven
