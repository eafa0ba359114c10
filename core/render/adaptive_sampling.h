#pragma once
// Adaptive sampling (`--noise-threshold T`): which pixels the next pass of a render samples.
// Every pixel takes the first kMinSamples passes; after that, a pixel stops for good once the
// estimated relative error of its mean falls below T, and the render ends when every pixel has
// stopped or the samples per pixel are spent. Decisions are made between whole passes from the
// pass values alone (no clock, no thread order), so a render stays a pure function of (scene,
// seed, settings), and the samples of every pixel are the first N of the render's range.
//
// The error estimate of pixel j after n_j samples: e_j^2 = max(v_j, vbar_j) / n_j, where v_k,
// pixel k's relative variance per sample, is sum_c s_c^2 / sum_c (m_c^2 + eps) with s_c^2 the
// sample variance of channel c's pass values and m_c their mean, and vbar_j is the mean of v_k
// over the 3 x 3 pixels around j. eps = 0.01 as in woven converge's relMSE, so a dark pixel's
// error is measured against 0.1, not its own tiny value. The sample variance has n - 1 degrees
// of freedom where the difference of two half buffers has one; the neighbourhood, where the
// integrand is much the same, steadies it further, so that a pixel seldom stops on a lucky run of
// samples; and the maximum keeps an edge pixel from stopping early because its neighbours on
// one side (a flat sky) have no variance.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace woven {

class AdaptiveSampling {
public:
    // Passes every pixel takes before any may stop: enough for a variance to mean something.
    static constexpr int kMinSamples = 16;

    // threshold: the relative error at which a pixel stops (> 0).
    AdaptiveSampling(int width, int height, double threshold);

    // 1 for each pixel the next pass samples, 0 for those that have stopped.
    const std::vector<uint8_t>& active() const { return active_; }
    size_t activeCount() const { return activeCount_; }

    // Adds a pass: `values` holds the pass's estimate of every pixel it sampled (entries of
    // stopped pixels are not read), as PassImage::combined() gives it. Then stops the pixels
    // whose error is below the threshold.
    void addPass(const std::vector<glm::vec3>& values);

    // e_j above: the estimated relative error of pixel (x, y)'s mean; infinite until it and its
    // neighbours have two samples each.
    double relativeError(int x, int y) const;

private:
    double relativeVariance(size_t pixel) const;  // v_k above

    int width_, height_;
    double threshold_;
    int passes_ = 0;
    // Per pixel: the running mean and sum of squared deviations (Welford) of its pass values,
    // per channel, and their count.
    std::vector<glm::vec3> mean_, m2_;
    std::vector<uint32_t> count_;
    std::vector<double> variance_;  // v_k above; infinite before two samples
    std::vector<uint8_t> active_;
    size_t activeCount_;
};

}  // namespace woven
