#include "sure_selection.h"

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace woven {

namespace {

// The mean over the (2 radius + 1)^2 box around each pixel, cut at the frame's edge: a running
// sum along rows, then along columns.
std::vector<float> boxMean(const std::vector<float>& image, int width, int height, int radius) {
    std::vector<float> rows(image.size()), out(image.size());
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
        for (int y = range.begin(); y != range.end(); ++y) {
            const float* in = &image[size_t(y) * width];
            for (int x = 0; x < width; ++x) {
                float sum = 0.0f;
                const int a = std::max(0, x - radius), b = std::min(width - 1, x + radius);
                for (int t = a; t <= b; ++t) sum += in[t];
                rows[size_t(y) * width + x] = sum / float(b - a + 1);
            }
        }
    });
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
        for (int y = range.begin(); y != range.end(); ++y) {
            const int a = std::max(0, y - radius), b = std::min(height - 1, y + radius);
            float* o = &out[size_t(y) * width];
            std::fill(o, o + width, 0.0f);
            for (int t = a; t <= b; ++t) {
                const float* in = &rows[size_t(t) * width];
                for (int x = 0; x < width; ++x) o[x] += in[x];
            }
            for (int x = 0; x < width; ++x) o[x] /= float(b - a + 1);
        }
    });
    return out;
}

}  // namespace

std::vector<glm::vec3> selectBySure(int width, int height, const std::vector<std::vector<glm::vec3>>& candidates,
                                    const std::vector<std::vector<float>>& risk, int radius) {
    const size_t n = size_t(width) * size_t(height), count = candidates.size();
    if (count == 1) return candidates[0];
    std::vector<std::vector<float>> smoothed(count);
    for (size_t k = 0; k < count; ++k) smoothed[k] = boxMean(risk[k], width, height, radius);
    std::vector<std::vector<float>> chosen(count, std::vector<float>(n, 0.0f));
    for (size_t i = 0; i < n; ++i) {
        size_t best = 0;
        for (size_t k = 1; k < count; ++k)
            if (smoothed[k][i] < smoothed[best][i]) best = k;
        chosen[best][i] = 1.0f;
    }
    std::vector<glm::vec3> out = candidates[0];
    for (size_t k = 1; k < count; ++k) {
        const std::vector<float> share = boxMean(chosen[k], width, height, radius);
        for (size_t i = 0; i < n; ++i)
            if (share[i] > 0.0f) out[i] += share[i] * (candidates[k][i] - candidates[0][i]);
    }
    return out;
}

}  // namespace woven
