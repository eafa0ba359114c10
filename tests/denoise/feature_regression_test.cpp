// The regression candidate's weighted least-squares fit (feature_regression.h) against the
// closed forms of a straight-line fit with equal weights.
#include "feature_regression.h"

#include <gtest/gtest.h>

#include <cmath>

namespace woven {
namespace {

constexpr int kWidth = 9, kPad = 4;

// One row of kWidth pixels, albedo 0 (nothing divided out), the depth constant and the direct
// light's red channel x, its green and blue 0; the colour u.
DenoiseBuffers row(const std::vector<float>& x, const std::vector<float>& u) {
    DenoiseBuffers b;
    b.width = kWidth;
    b.height = 1;
    for (int i = 0; i < kWidth; ++i) {
        b.color.push_back(glm::vec3(u[size_t(i)]));
        b.variance.push_back(glm::vec3(0.01f));
        b.albedo.push_back(glm::vec3(0.0f));
        b.depth.push_back(1.0f);
        b.direct.push_back(glm::vec3(x[size_t(i)], 0.0f, 0.0f));
    }
    return b;
}

// The fit at the middle pixel over the whole row, every neighbour of weight 1.
FeatureRegression::Fit fitAtCentre(const DenoiseBuffers& b, float ridge) {
    const Demodulated d = demodulate(b);
    const FeatureRegression regression(b, d, kPad);
    const PaddedPlanes u(b.width, b.height, 3, kPad, [&](size_t i, int c) { return d.irradiance.c[size_t(c)][i]; });
    FeatureRegression::Sums sums(1);
    const int centre = kWidth / 2;
    const size_t p = u.index(centre, 0);
    const float* planes[3] = {u.plane(0) + p, u.plane(1) + p, u.plane(2) + p};
    const float one = 1.0f;
    for (int dx = -centre; dx <= centre; ++dx)
        if (dx != 0) regression.accumulate(p, dx, 1, &one, planes, sums, 0);
    return regression.solve(sums, 0, size_t(centre), ridge);
}

TEST(FeatureRegression, ALinearSignalIsFittedExactly) {
    // u = 0.3 + 2 x: the fit at the centre is its own colour, whatever x is there.
    std::vector<float> x, u;
    for (int i = 0; i < kWidth; ++i) {
        x.push_back(0.1f * float(i * i % 7));
        u.push_back(0.3f + 2.0f * x.back());
    }
    const FeatureRegression::Fit fit = fitAtCentre(row(x, u), 1e-7f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fit.change[c], 0.0f, 1e-5f);
}

TEST(FeatureRegression, LeverageIsTheStraightLineFitsAndTheRidgeShrinksTheSlope) {
    // Noise about a line: the fit's value at the centre and its derivative in the centre's own
    // colour are those of ordinary least squares, a + b x_p with b = Sxy / Sxx, and the leverage
    // 1 / n + (x_p - mean x)^2 / Sxx.
    const std::vector<float> x = {0.0f, 0.5f, 0.2f, 0.9f, 0.4f, 0.7f, 0.1f, 0.8f, 0.3f};
    const std::vector<float> u = {1.0f, 1.6f, 1.1f, 2.1f, 1.3f, 1.8f, 1.3f, 1.9f, 1.2f};
    double mx = 0.0, mu = 0.0;
    for (int i = 0; i < kWidth; ++i) {
        mx += x[size_t(i)] / kWidth;
        mu += u[size_t(i)] / kWidth;
    }
    double sxx = 0.0, sxy = 0.0;
    for (int i = 0; i < kWidth; ++i) {
        sxx += (x[size_t(i)] - mx) * (x[size_t(i)] - mx);
        sxy += (x[size_t(i)] - mx) * (u[size_t(i)] - mu);
    }
    const int c = kWidth / 2;
    const double slope = sxy / sxx, atCentre = mu + slope * (x[size_t(c)] - mx);
    const double leverage = 1.0 / kWidth + (x[size_t(c)] - mx) * (x[size_t(c)] - mx) / sxx;
    const FeatureRegression::Fit fit = fitAtCentre(row(x, u), 1e-7f);
    EXPECT_NEAR(fit.change[0], atCentre - u[size_t(c)], 1e-5);
    EXPECT_NEAR(fit.leverage, leverage, 1e-5);
    // A strong ridge leaves the window's mean: the slope shrinks towards 0.
    const FeatureRegression::Fit ridged = fitAtCentre(row(x, u), 1e4f);
    EXPECT_NEAR(ridged.change[0], mu - u[size_t(c)], 1e-3);
    EXPECT_NEAR(ridged.leverage, 1.0 / kWidth, 1e-3);
}

TEST(FeatureRegression, ANoisyPassIsTakenAtTheWindowsMean) {
    // Where the pixel's pass is all noise (its variance above the window's spread), the fit is
    // evaluated at the window's mean pass, where a straight-line fit is the window's mean colour:
    // the pixel's own pass, and its noise, no longer move the estimate.
    const std::vector<float> x = {0.0f, 0.5f, 0.2f, 0.9f, 0.4f, 0.7f, 0.1f, 0.8f, 0.3f};
    const std::vector<float> u = {1.0f, 1.6f, 1.1f, 2.1f, 1.3f, 1.8f, 1.3f, 1.9f, 1.2f};
    double mu = 0.0;
    for (float v : u) mu += v / kWidth;
    DenoiseBuffers b = row(x, u);
    b.directVariance.assign(kWidth, glm::vec3(1e6f));
    const FeatureRegression::Fit fit = fitAtCentre(b, 1e-7f);
    EXPECT_NEAR(fit.change[0], mu - u[kWidth / 2], 1e-5);
    EXPECT_NEAR(fit.leverage, 1.0 / kWidth, 1e-5);
    // A pass without noise is taken as it is (the test above).
    b.directVariance.assign(kWidth, glm::vec3(0.0f));
    const FeatureRegression::Fit exact = fitAtCentre(b, 1e-7f);
    EXPECT_GT(std::fabs(exact.change[0] - fit.change[0]), 1e-3f);
}

}  // namespace
}  // namespace woven
