// SURE and the choice it makes among candidate filters (sure_selection.h), on frames with a known
// truth and Gaussian noise from fixed seeds.
#include "sure_selection.h"

#include <gtest/gtest.h>

#include <random>

namespace woven {
namespace {

TEST(SureSelection, RiskOfABoxMeanIsItsMeanSquaredError) {
    // A 3 x 3 box mean of noise sigma: F - truth has variance sigma^2 / 9, and dF/dy = 1 / 9.
    constexpr int kSize = 256;
    constexpr float kSigma = 0.1f, kTruth = 0.5f;
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, kSigma);
    std::vector<float> y(size_t(kSize) * kSize);
    for (float& v : y) v = kTruth + noise(rng);
    double risk = 0.0, withoutDerivative = 0.0, error = 0.0;
    int count = 0;
    for (int py = 1; py + 1 < kSize; ++py)
        for (int px = 1; px + 1 < kSize; ++px) {
            float mean = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) mean += y[size_t(py + dy) * kSize + px + dx];
            mean /= 9.0f;
            const float change = mean - y[size_t(py) * kSize + px], variance = kSigma * kSigma;
            risk += steinUnbiasedRisk(change, variance, 1.0f / 9.0f);
            withoutDerivative += steinUnbiasedRisk(change, variance, 0.0f);
            error += double(mean - kTruth) * double(mean - kTruth);
            ++count;
        }
    risk /= count;
    withoutDerivative /= count;
    error /= count;
    const double expected = kSigma * kSigma / 9.0;
    // 64516 pixels: SURE's own spread, about sigma^2 a pixel, falls to 0.4 % of sigma^2 in their
    // mean, 3.5 % of the expected 1.1e-3 (its neighbours are correlated, so a little more): 15 % is
    // four times that. The actual error holds to the same.
    EXPECT_NEAR(error, expected, 0.15 * expected);
    EXPECT_NEAR(risk, error, 0.15 * expected) << "SURE " << risk << ", actual " << error;
    // The derivative term is what makes it unbiased: without it the estimate is 2 sigma^2 / 9 low.
    EXPECT_LT(withoutDerivative, 0.0);
}

TEST(SureSelection, EachPixelTakesTheCandidateOfLeastRiskAroundIt) {
    // Candidate 0 is the less risky on the left half, candidate 1 on the right; a 3 x 3 box.
    constexpr int kWidth = 32, kHeight = 8;
    const size_t n = size_t(kWidth) * kHeight;
    const std::vector<std::vector<glm::vec3>> candidates = {std::vector<glm::vec3>(n, glm::vec3(0.2f)),
                                                            std::vector<glm::vec3>(n, glm::vec3(0.8f))};
    std::vector<std::vector<float>> risk(2, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i) {
        const bool left = int(i % kWidth) < kWidth / 2;
        risk[0][i] = left ? 1.0f : 2.0f;
        risk[1][i] = left ? 2.0f : 1.0f;
    }
    const std::vector<glm::vec3> out = selectBySure(kWidth, kHeight, candidates, risk, 1);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            // Beside the border the box holds one or two columns of the other side's choice.
            const float expected = x < 15 ? 0.2f : x == 15 ? 0.2f + 0.6f / 3.0f : x == 16 ? 0.2f + 0.6f * 2.0f / 3.0f : 0.8f;
            EXPECT_NEAR(out[size_t(y) * kWidth + x].x, expected, 1e-6f) << "pixel " << x << ", " << y;
        }
}

TEST(SureSelection, CandidatesThatAgreeGiveTheirFrameExactly) {
    // However the choice falls, a pixel where every candidate has the same colour keeps it bit for
    // bit (a blend of equal values in floats need not).
    constexpr int kWidth = 16, kHeight = 16;
    const size_t n = size_t(kWidth) * kHeight;
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec3> frame(n);
    for (glm::vec3& c : frame) c = glm::vec3(u(rng), u(rng), u(rng));
    std::vector<std::vector<float>> risk(3, std::vector<float>(n));
    for (auto& r : risk)
        for (float& v : r) v = u(rng);
    const std::vector<glm::vec3> out = selectBySure(kWidth, kHeight, {frame, frame, frame}, risk, 2);
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(out[i], frame[i]) << "pixel " << i;
}

}  // namespace
}  // namespace woven
