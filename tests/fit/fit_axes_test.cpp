// The fit's search axes (core/fit/fit_axes.h) and its optimiser (core/fit/bobyqa.h), pulled out of
// the fit: a material survives the unit box, ranges are held, and BOBYQA finds a bowl's bottom,
// keeps the best point it met and stops when told.
#include <gtest/gtest.h>

#include <cmath>

#include "bobyqa.h"
#include "fit_axes.h"

namespace woven {
namespace {

TEST(FitAxes, AMaterialWithinTheRangesSurvivesEncodeAndDecode) {
    WovenParams p;
    p.weft_color = {0.7f, 0.62f, 0.45f};
    p.warp_color = {0.1f, 0.16f, 0.42f};
    p.rs = 0.05f;
    p.ex = p.warp_ex = 60.0f;
    p.ey = p.warp_ey = 4.0f;
    p.yarn_width = 0.85f;
    p.warp_width = 0.9f;
    p.cy = 0.6f;
    const std::vector<double> x = encode(p);
    ASSERT_EQ(x.size(), fullAxes().size());
    for (double v : x) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
    }
    const WovenParams q = decode(x, WovenParams{});
    EXPECT_NEAR(q.weft_color.g, 0.62f, 1e-5f);
    EXPECT_NEAR(q.warp_color.b, 0.42f, 1e-5f);
    EXPECT_NEAR(q.rs, 0.05f, 1e-6f);
    EXPECT_NEAR(q.ex, 60.0f, 1e-3f);
    EXPECT_EQ(q.warp_ex, q.ex) << "the warp's gloss follows the weft's";
    EXPECT_NEAR(q.ey, 4.0f, 1e-4f);
    EXPECT_NEAR(q.warp_width, 0.9f, 1e-6f);
    EXPECT_NEAR(q.cy, 0.6f, 1e-6f);
}

TEST(FitAxes, ColoursAloneLeaveTheShapeAsItWas) {
    WovenParams p;
    p.rs = 0.2f;
    p.ex = 7.0f;
    std::vector<double> x = encode(p);
    x.resize(kColourAxes);
    x[0] = 1.0;
    const WovenParams q = decode(x, p);
    EXPECT_FLOAT_EQ(q.weft_color.r, 1.0f);
    EXPECT_FLOAT_EQ(q.rs, 0.2f);
    EXPECT_FLOAT_EQ(q.ex, 7.0f);
}

TEST(FitAxes, ValuesOutsideAnAxisAreHeldAtItsEnds) {
    const Axis& rs = fullAxes()[kRsAxis];  // 10^-3 to 10^-0.3
    EXPECT_NEAR(rs.clamped(2.0), std::pow(10.0, -0.3), 1e-12);
    EXPECT_NEAR(rs.clamped(0.0), 0.001, 1e-12);
    EXPECT_NEAR(rs.unit(std::pow(10.0, -1.65)), 0.5, 1e-12) << "a log axis's middle is the ends' geometric mean";
}

TEST(Bobyqa, FindsABowlsBottomInsideTheBox) {
    std::vector<double> x{0.9, 0.1};
    const int n = minimiseInUnitBox(
        x, [](const std::vector<double>& v) { return std::pow(v[0] - 0.3, 2) + 2.0 * std::pow(v[1] - 0.7, 2); }, 0,
        [] { return false; });
    EXPECT_GT(n, 0);
    EXPECT_NEAR(x[0], 0.3, 1e-3);
    EXPECT_NEAR(x[1], 0.7, 1e-3);
}

TEST(Bobyqa, StopsWhenToldAndKeepsTheBestPointMet) {
    std::vector<double> x{0.5};
    int calls = 0;
    double best = INFINITY;
    const int n = minimiseInUnitBox(
        x,
        [&](const std::vector<double>& v) {
            const double f = std::abs(v[0] - 0.9);
            best = std::min(best, f);
            return f;
        },
        0, [&] { return ++calls > 4; });
    EXPECT_EQ(n, 4);
    EXPECT_DOUBLE_EQ(std::abs(x[0] - 0.9), best);
}

}  // namespace
}  // namespace woven
