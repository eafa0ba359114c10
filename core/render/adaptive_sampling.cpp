#include "adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace woven {

namespace {
// Added to each channel's squared mean: errors of pixels darker than about 0.1 are measured
// against 0.1 (woven converge's relMSE weighs pixels the same way).
constexpr double kEps = 1e-2;
}  // namespace

AdaptiveSampling::AdaptiveSampling(int width, int height, double threshold)
    : width_(width), height_(height), threshold_(threshold), mean_(size_t(width) * height, glm::vec3(0.0f)),
      m2_(mean_.size(), glm::vec3(0.0f)), count_(mean_.size(), 0),
      variance_(mean_.size(), std::numeric_limits<double>::infinity()), active_(mean_.size(), 1), activeCount_(mean_.size()) {
    if (!(threshold > 0.0)) throw std::invalid_argument("the noise threshold of adaptive sampling must be positive");
}

void AdaptiveSampling::addPass(const std::vector<glm::vec3>& values) {
    // Each pixel's figures are its own, and stopping a pixel changes no variance, so the rows may
    // go in any order on any thread (the calling arena's) and decide the same.
    const auto eachRow = [&](auto&& f) {
        tbb::parallel_for(tbb::blocked_range<int>(0, height_), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y) f(y);
        });
    };
    eachRow([&](int y) {
        for (size_t i = size_t(y) * width_, end = i + size_t(width_); i < end; ++i) {
            if (!active_[i]) continue;
            const glm::vec3 delta = values[i] - mean_[i];
            mean_[i] += delta / float(++count_[i]);
            m2_[i] += delta * (values[i] - mean_[i]);
            variance_[i] = relativeVariance(i);
        }
    });
    if (++passes_ < kMinSamples) return;
    std::vector<uint8_t> stops(active_.size(), 0);
    eachRow([&](int y) {
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * width_ + x;
            stops[i] = active_[i] && relativeError(x, y) < threshold_;
        }
    });
    for (size_t i = 0; i < active_.size(); ++i)
        if (stops[i]) {
            active_[i] = 0;
            --activeCount_;
        }
}

double AdaptiveSampling::relativeVariance(size_t i) const {
    if (count_[i] < 2) return std::numeric_limits<double>::infinity();
    const glm::dvec3 m(mean_[i]), s2 = glm::dvec3(m2_[i]) / double(count_[i] - 1);
    return (s2.x + s2.y + s2.z) / (m.x * m.x + m.y * m.y + m.z * m.z + 3.0 * kEps);
}

double AdaptiveSampling::relativeError(int x, int y) const {
    double pooled = 0.0;
    int n = 0;
    for (int v = std::max(y - 1, 0); v <= std::min(y + 1, height_ - 1); ++v)
        for (int u = std::max(x - 1, 0); u <= std::min(x + 1, width_ - 1); ++u, ++n)
            pooled += variance_[size_t(v) * width_ + u];
    const size_t i = size_t(y) * width_ + x;
    return std::sqrt(std::max(variance_[i], pooled / n) / count_[i]);
}

}  // namespace woven
