// The weave tile (MODEL.md section 1): top-yarn maps against MODEL.md's drawings and against
// the formula d = (U + k V) mod (i + j) evaluated here, floats, periodicity, huge coordinates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "weave_pattern.h"
#include "yarn_geometry.h"

namespace woven {
namespace {

// MODEL.md's formula, written independently: true where warp is on top.
bool referenceWarp(int i, int j, int k, int64_t U, int64_t V) {
    const int64_t period = i + j;
    int64_t d = (U % period + (int64_t(k) % period) * (V % period)) % period;
    if (d < 0) d += period;
    return d >= i;
}

// The float of the top yarn through (U, V), as the crimp looks it up.
WeavePattern::Float floatAt(const WeavePattern& p, const WeaveFloats& floats, int64_t U, int64_t V) {
    return floats.at(U, V, p.top(U, V));
}

std::string drawRows(const std::vector<std::string>& rows) {
    std::string s;
    for (const auto& r : rows) s += r + "\n";
    return s;
}

TEST(WeavePattern, PlainTwillSatinMatchModelDrawings) {
    // Copied from MODEL.md section 1.
    EXPECT_EQ(WeavePattern::regular(1, 1, 1).draw(8, 3), drawRows({"-|-|-|-|", "|-|-|-|-", "-|-|-|-|"}));
    EXPECT_EQ(WeavePattern::regular(1, 2, 1).draw(12, 3),
              drawRows({"-||-||-||-||", "||-||-||-||-", "|-||-||-||-|"}));
    EXPECT_EQ(WeavePattern::regular(9, 1, 3).draw(20, 3),
              drawRows({"---------|---------|", "------|---------|---", "---|---------|------"}));
}

TEST(WeavePattern, TileSizeIsThePeriod) {
    struct Case { int i, j, k, pu, pv; };
    const Case cases[] = {
        {1, 1, 1, 2, 2}, {1, 2, 1, 3, 3}, {9, 1, 3, 10, 10}, {2, 2, 2, 4, 2},
        {3, 1, 0, 4, 1},   // k = 0: every row the same
        {1, 0, 0, 1, 1},   // i + j = 1
        {0, 1, 7, 1, 1},
        {32, 32, 8, 64, 8},   // i + j = 64
        {5, 59, 7, 64, 64},
        {1, 2, 4, 3, 3},      // k >= i + j
        {2, 3, 10, 5, 1},     // k a multiple of i + j
    };
    for (const Case& c : cases) {
        const WeavePattern p = WeavePattern::regular(c.i, c.j, c.k);
        EXPECT_EQ(p.width(), c.pu) << c.i << "," << c.j << "," << c.k;
        EXPECT_EQ(p.height(), c.pv) << c.i << "," << c.j << "," << c.k;
    }
}

TEST(WeavePattern, MatchesFormulaForManyPatterns) {
    const int triples[][3] = {{1, 1, 1}, {1, 2, 1}, {9, 1, 3}, {2, 1, 1}, {3, 1, 0}, {1, 3, 5}, {4, 4, 12},
                              {1, 0, 0}, {0, 1, 3}, {32, 32, 8}, {5, 59, 7}, {63, 1, 64}, {1, 63, 200}};
    for (const auto& t : triples) {
        const WeavePattern p = WeavePattern::regular(t[0], t[1], t[2]);
        for (int64_t V = -70; V < 70; V += 3)
            for (int64_t U = -70; U < 70; ++U)
                ASSERT_EQ(p.top(U, V) == YarnType::Warp, referenceWarp(t[0], t[1], t[2], U, V))
                    << "(" << t[0] << "," << t[1] << "," << t[2] << ") U=" << U << " V=" << V;
    }
}

TEST(WeavePattern, ShiftAtOrBeyondPeriodEqualsShiftModPeriod) {
    for (int k = 0; k < 3; ++k)
        for (int m = 1; m <= 3; ++m)
            EXPECT_EQ(WeavePattern::regular(1, 2, k + 3 * m).draw(9, 9), WeavePattern::regular(1, 2, k).draw(9, 9))
                << "k = " << k + 3 * m;
    // k = 0: all rows equal.
    const std::string rows = WeavePattern::regular(2, 3, 0).draw(10, 4);
    EXPECT_EQ(rows, drawRows({"--|||--|||", "--|||--|||", "--|||--|||", "--|||--|||"}));
}

TEST(WeavePattern, SingleYarnPatterns) {
    EXPECT_EQ(WeavePattern::regular(1, 0, 0).draw(4, 2), "----\n----\n");
    EXPECT_EQ(WeavePattern::regular(0, 1, 5).draw(4, 2), "||||\n||||\n");
    // A yarn on top along its whole period: its float is the period.
    const WeavePattern weft = WeavePattern::regular(1, 0, 0);
    const WeaveFloats weftFloats(weft);
    EXPECT_EQ(floatAt(weft, weftFloats, 5, -3).length, 1);
    EXPECT_EQ(floatAt(weft, weftFloats, 5, -3).position, 0);
}

TEST(WeavePattern, LargeTileRowCounts) {
    const WeavePattern p = WeavePattern::regular(5, 59, 7);
    for (int V = 0; V < 64; ++V) {
        int warp = 0;
        for (int U = 0; U < 64; ++U) warp += p.top(U, V) == YarnType::Warp;
        EXPECT_EQ(warp, 59) << "row " << V;
    }
    for (int U = 0; U < 64; ++U) {
        int warp = 0;
        for (int V = 0; V < 64; ++V) warp += p.top(U, V) == YarnType::Warp;
        EXPECT_EQ(warp, 59) << "column " << U;  // gcd(7, 64) = 1: each column sees every d once
    }
    const WeavePattern q = WeavePattern::regular(32, 32, 8);
    for (int V = 0; V < 8; ++V) {
        int weft = 0;
        for (int U = 0; U < 64; ++U) weft += q.top(U, V) == YarnType::Weft;
        EXPECT_EQ(weft, 32);
    }
}

TEST(WeavePattern, PeriodicAndSafeForHugeAndNegativeIndices) {
    const WeavePattern p = WeavePattern::regular(9, 1, 3);
    const WeaveFloats pFloats(p);
    const int64_t bigs[] = {1000000, -1000000, 999999937, -999999937, int64_t(1) << 40, -(int64_t(1) << 40),
                            INT64_MAX / 2, INT64_MIN / 2};
    for (int64_t big : bigs)
        for (int64_t U = -12; U < 12; ++U)
            for (int64_t V = -12; V < 12; ++V)
                ASSERT_EQ(p.top(U + big, V) == YarnType::Warp, referenceWarp(9, 1, 3, U + big, V))
                    << "U=" << U + big << " V=" << V;
    for (int64_t U = -25; U < 25; ++U)
        for (int64_t V = -25; V < 25; ++V) {
            EXPECT_EQ(p.top(U, V), p.top(U + 10, V));
            EXPECT_EQ(p.top(U, V), p.top(U, V + 10));
            EXPECT_EQ(floatAt(p, pFloats, U, V).position, floatAt(p, pFloats, U + 10, V - 20).position);
        }
}

// Independent float computation: walk the reference map along the yarn's direction.
WeavePattern::Float referenceFloat(const std::function<bool(int64_t, int64_t)>& warpAt, int64_t U, int64_t V,
                                   int period) {
    const bool warp = warpAt(U, V);
    const int du = warp ? 0 : 1, dv = warp ? 1 : 0;
    int before = 0, after = 0;
    while (before < period && warpAt(U - du * (before + 1), V - dv * (before + 1)) == warp) ++before;
    if (before == period) return {int(((warp ? V : U) % period + period) % period), period};
    while (warpAt(U + du * (after + 1), V + dv * (after + 1)) == warp) ++after;
    return {before, before + after + 1};
}

TEST(WeavePattern, FloatsStartAndLength) {
    const int triples[][3] = {{9, 1, 3}, {1, 1, 1}, {1, 2, 1}, {3, 2, 1}, {4, 4, 1}, {5, 59, 7}, {2, 1, 0}};
    for (const auto& t : triples) {
        const WeavePattern p = WeavePattern::regular(t[0], t[1], t[2]);
        const WeaveFloats pFloats(p);
        auto warpAt = [&](int64_t U, int64_t V) { return referenceWarp(t[0], t[1], t[2], U, V); };
        for (int64_t V = -3; V < p.height() + 3; ++V)
            for (int64_t U = -3; U < p.width() + 3; ++U) {
                const int period = warpAt(U, V) ? p.height() : p.width();
                const auto expected = referenceFloat(warpAt, U, V, period);
                const auto f = floatAt(p, pFloats, U, V);
                ASSERT_EQ(f.length, expected.length) << t[0] << t[1] << t[2] << " U=" << U << " V=" << V;
                if (expected.length < period) {
                    ASSERT_EQ(f.position, expected.position) << " U=" << U << " V=" << V;
                }
                ASSERT_GE(f.position, 0);
                ASSERT_LT(f.position, f.length);
            }
    }
    // Satin (9, 1, 3): weft floats of 9 in row 0 start right after the warp at U = 9.
    const WeavePattern satin = WeavePattern::regular(9, 1, 3);
    const WeaveFloats satinFloats(satin);
    for (int U = 0; U < 9; ++U) {
        EXPECT_EQ(floatAt(satin, satinFloats, U, 0).length, 9);
        EXPECT_EQ(floatAt(satin, satinFloats, U, 0).position, U);
    }
    EXPECT_EQ(floatAt(satin, satinFloats, 9, 0).length, 1);  // the warp crossing over
    // Row 1 "------|---------|---": the float through U = 0 started at U = -3 (i.e. 7).
    EXPECT_EQ(floatAt(satin, satinFloats, 0, 1).position, 3);
    EXPECT_EQ(floatAt(satin, satinFloats, 5, 1).position, 8);
}

TEST(WeavePattern, GeneralTileFromParams) {
    WovenParams params;
    params.tile = {"-||-", "|--|", "--||"};  // hand-drawn, not of the (i, j, k) family
    const WeavePattern p = WeavePattern::fromParams(params);
    const WeaveFloats pFloats(p);
    EXPECT_EQ(p.width(), 4);
    EXPECT_EQ(p.height(), 3);
    EXPECT_EQ(p.draw(8, 4), drawRows({"-||--||-", "|--||--|", "--||--||", "-||--||-"}));
    // Row 0 "-||-" wraps: weft float of 2 through U = 3, 0 (starting at U = 3).
    EXPECT_EQ(floatAt(p, pFloats, 3, 0).length, 2);
    EXPECT_EQ(floatAt(p, pFloats, 3, 0).position, 0);
    EXPECT_EQ(floatAt(p, pFloats, 0, 0).position, 1);
    // Column 3 is '-', '|', '|' down V: warp float of 2 starting at V = 1.
    EXPECT_EQ(floatAt(p, pFloats, 3, 1).length, 2);
    EXPECT_EQ(floatAt(p, pFloats, 3, 2).position, 1);
    // Column 1 '|', '-', '-': warp float of 1.
    EXPECT_EQ(floatAt(p, pFloats, 1, 0).length, 1);

    // The (i, j, k) family goes through the same tile code: drawing it as a tile gives the same.
    WovenParams twill;
    twill.tile = {"-||", "||-", "|-|"};
    EXPECT_EQ(WeavePattern::fromParams(twill).draw(12, 6), WeavePattern::regular(1, 2, 1).draw(12, 6));

    EXPECT_THROW(WeavePattern::fromRows({}), std::invalid_argument);
    EXPECT_THROW(WeavePattern::fromRows({"-|", "-"}), std::invalid_argument);
    EXPECT_THROW(WeavePattern::fromRows({"-x"}), std::invalid_argument);
    EXPECT_THROW(WeavePattern::regular(0, 0, 1), std::invalid_argument);
    EXPECT_THROW(WeavePattern::regular(-1, 2, 1), std::invalid_argument);
}

TEST(WeavePattern, ReversedIsTheBackFace) {
    const WeavePattern front = WeavePattern::regular(9, 1, 3);
    const WeavePattern back = front.reversed();
    const WeaveFloats frontFloats(front);  // a run is a run on either face: one table serves both
    EXPECT_EQ(back.width(), front.width());
    EXPECT_EQ(back.height(), front.height());
    for (int V = 0; V < 10; ++V)
        for (int U = 0; U < 10; ++U) {
            EXPECT_NE(back.top(U, V), front.top(U, V));
            // Satin's back: warp floats of 9 along V where the front had weft floats along U.
            EXPECT_EQ(floatAt(back, frontFloats, U, V).length, back.top(U, V) == YarnType::Warp ? 9 : 1);
        }
    EXPECT_EQ(back.reversed().draw(10, 10), front.draw(10, 10));
}

// yarnAt at huge and negative coordinates matches the same point moved near the origin.
TEST(WeavePattern, YarnAtHugeAndNegativeCoordinatesMatchesSmallEquivalent) {
    WovenParams params;
    params.pattern = {9, 1, 3};
    params.cy = 0.8f;
    params.yarn_width = 0.8f;
    params.warp_width = 0.7f;
    params.crimp = 0.5f;
    const Weave p(params);
    const double offsets[][2] = {{1e6, 1e6}, {-1e6, -1e6}, {1e6, -1e6}, {-20.0, -30.0}, {1e6 + 10, 3e6}};
    for (const auto& o : offsets) {
        for (int n = 0; n < 2000; ++n) {
            const glm::dvec2 small(0.00731 * n + 0.1234567, 0.0037 * n + 0.0123457 * (n % 13));
            const glm::dvec2 far = small + glm::dvec2(o[0], o[1]);  // offsets are multiples of the 10 x 10 tile
            const YarnPoint a = yarnAt(p, params, false, small), b = yarnAt(p, params, false, far);
            ASSERT_EQ(a.type, b.type) << far.x << "," << far.y;
            ASSERT_NEAR(a.normal.x, b.normal.x, 2e-3f);  // double keeps ~1e-10 of the element at 1e6
            ASSERT_NEAR(a.normal.y, b.normal.y, 2e-3f);
            ASSERT_NEAR(a.normal.z, b.normal.z, 2e-3f);
            if (b.type != YarnType::Gap) {
                const int64_t expectedIndex = int64_t(std::floor(b.type == YarnType::Weft ? far.y : far.x));
                ASSERT_EQ(b.yarnIndex, expectedIndex);
            }
        }
    }
    // Repeat counts multiply the coordinates: 1e6 elements per unit at u = 1e6 is element 1e12.
    params.repeat = {1e6f, 1e6f};
    const YarnPoint far = yarnAt(p, params, false, glm::dvec2(1e6, -1e6) + glm::dvec2(0.5e-6, 0.5e-6));
    const bool warp = referenceWarp(9, 1, 3, 1000000000000LL, -1000000000000LL);
    EXPECT_EQ(far.type, warp ? YarnType::Warp : YarnType::Weft);
    EXPECT_EQ(far.yarnIndex, warp ? 1000000000000LL : -1000000000000LL);
}

}  // namespace
}  // namespace woven
