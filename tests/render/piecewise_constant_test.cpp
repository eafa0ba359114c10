#include "piecewise_constant.h"

#include <gtest/gtest.h>

#include "sampling.h"
#include "statistics.h"

namespace woven {
namespace {

TEST(PiecewiseConstant1D, ContinuousSamplesFollowTheFunction) {
    const std::vector<float> func = {1.0f, 0.0f, 3.0f, 0.5f, 2.5f};
    PiecewiseConstant1D dist(func);
    EXPECT_FLOAT_EQ(dist.integral(), 7.0f / 5.0f);
    const int n = 100000;
    std::vector<double> observed(func.size(), 0.0), expected(func.size());
    for (size_t i = 0; i < func.size(); ++i) expected[i] = n * func[i] / 7.0;
    Rng rng(1);
    for (int s = 0; s < n; ++s) {
        float pdf;
        int offset;
        const float x = dist.sampleContinuous(rng.uniform(), &pdf, &offset);
        ASSERT_GE(x, 0.0f);
        ASSERT_LT(x, 1.0f);
        ASSERT_EQ(offset, int(x * 5.0f));
        ASSERT_NE(offset, 1) << "a piece of zero weight was sampled";
        // The density of a piece is its share of the integral times the number of pieces.
        ASSERT_NEAR(pdf, func[offset] / 7.0f * 5.0f, 1e-5f);
        ASSERT_NEAR(dist.pdf(x), pdf, 1e-5f);
        observed[offset] += 1.0;
    }
    EXPECT_LT(test::chiSquareZ(observed, expected), 4.0);
}

TEST(PiecewiseConstant1D, DiscreteChoiceAndRemappedUniform) {
    PiecewiseConstant1D dist({2.0f, 6.0f, 0.0f, 2.0f});
    EXPECT_FLOAT_EQ(dist.discretePmf(0), 0.2f);
    EXPECT_FLOAT_EQ(dist.discretePmf(1), 0.6f);
    EXPECT_FLOAT_EQ(dist.discretePmf(2), 0.0f);
    float pmf, remapped;
    EXPECT_EQ(dist.sampleDiscrete(0.5f, &pmf, &remapped), 1);
    EXPECT_FLOAT_EQ(pmf, 0.6f);
    EXPECT_NEAR(remapped, 0.5f, 1e-6f);  // 0.5 sits halfway through [0.2, 0.8)
    EXPECT_EQ(dist.sampleDiscrete(0.8f, &pmf), 3);  // skips the empty piece
    EXPECT_EQ(dist.sampleDiscrete(0.0f, &pmf), 0);
    EXPECT_EQ(dist.sampleDiscrete(std::nextafter(1.0f, 0.0f), &pmf), 3);
}

TEST(PiecewiseConstant1D, AllZeroIsUniform) {
    PiecewiseConstant1D dist({0.0f, 0.0f, 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(dist.integral(), 0.0f);
    for (int i = 0; i < 4; ++i) EXPECT_FLOAT_EQ(dist.discretePmf(i), 0.25f);
    float pdf;
    EXPECT_NEAR(dist.sampleContinuous(0.3f, &pdf), 0.3f, 1e-6f);
    EXPECT_FLOAT_EQ(pdf, 1.0f);
}

TEST(PiecewiseConstant2D, SamplesFollowTheFunctionAndPdfMatches) {
    const int nu = 6, nv = 4;
    std::vector<float> func(nu * nv);
    double sum = 0.0;
    for (int v = 0; v < nv; ++v)
        for (int u = 0; u < nu; ++u) sum += func[v * nu + u] = (u == 2 && v == 1) ? 0.0f : float(1 + (u * 7 + v * 3) % 5);
    PiecewiseConstant2D dist(func, nu, nv);
    const int n = 200000;
    std::vector<double> observed(func.size(), 0.0), expected(func.size());
    for (size_t i = 0; i < func.size(); ++i) expected[i] = n * func[i] / sum;
    Rng rng(2);
    for (int s = 0; s < n; ++s) {
        float pdf;
        const glm::vec2 p = dist.sample(rng.uniform2(), &pdf);
        const int cell = int(p.y * nv) * nu + int(p.x * nu);
        // Density over the unit square: the cell's share of the total times the cell count.
        ASSERT_NEAR(pdf, func[cell] / sum * nu * nv, 1e-4);
        ASSERT_NEAR(dist.pdf(p), pdf, 1e-4f);
        observed[cell] += 1.0;
    }
    EXPECT_LT(test::chiSquareZ(observed, expected), 4.0);
}

}  // namespace
}  // namespace woven
