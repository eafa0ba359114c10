// Per-thread colours, yarn types and spacing (MODEL.md section 6) against values worked out by
// hand: which thread a point falls on, the colour and lobe it shades with, where gaps open, the
// far-field weights (the JSON keys: params_json_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "reference_brdf.h"
#include "weave_coverage.h"
#include "woven_material.h"
#include "yarn_geometry.h"

namespace woven {
namespace {

using test::kPi;

// The BSDF at normal incidence with rs = 0 is the diffuse term alone:
// 28 / (23 pi) R_d (1 - (1/2)^5)^2 (MODEL.md section 4).
const double kDiffuseAtNormal = 28.0 / (23.0 * kPi) * std::pow(1.0 - 1.0 / 32.0, 2.0);

// Flat yarns and no specular term, so shade() at a point gives its colour back exactly.
WovenParams matte() {
    WovenParams p;
    p.cy = 0.0f;
    p.rs = 0.0f;
    return p;
}

glm::vec3 colorAt(const WovenMaterial& m, glm::dvec2 uv) {
    ShadingInput in;
    in.uv = uv;
    const auto s = m.shade(in);
    EXPECT_TRUE(s.has_value());
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    return s->bsdf.eval(n, n) / float(kDiffuseAtNormal);
}

void expectColor(const glm::vec3& got, const glm::vec3& expected, const std::string& what) {
    EXPECT_NEAR(got.r, expected.r, 1e-5f) << what;
    EXPECT_NEAR(got.g, expected.g, 1e-5f) << what;
    EXPECT_NEAR(got.b, expected.b, 1e-5f) << what;
}

TEST(Threads, ColoursRepeatPerEndAndPerPick) {
    // Plain weave: weft on top where U + V is even. Three warp colours, two weft colours.
    const glm::vec3 red(0.8f, 0.1f, 0.1f), green(0.1f, 0.7f, 0.2f), blue(0.1f, 0.2f, 0.9f);
    const glm::vec3 white(0.9f), black(0.05f);
    WovenParams p = matte();
    p.warp_colors = {red, green, blue};
    p.weft_colors = {white, black};
    const WovenMaterial m(p);
    for (int V = -4; V < 8; ++V)
        for (int U = -7; U < 9; ++U) {
            const bool warpOnTop = ((U + V) % 2 + 2) % 2 == 1;
            const glm::vec3 expected = warpOnTop ? p.warp_colors[size_t(((U % 3) + 3) % 3)]
                                                 : p.weft_colors[size_t(((V % 2) + 2) % 2)];
            expectColor(colorAt(m, {U + 0.5, V + 0.5}), expected, "U=" + std::to_string(U) + " V=" + std::to_string(V));
        }
}

TEST(Threads, SpacingMakesCellsOfTheDraftsWidths) {
    // Warp spacing 1 and 3: the period of 2 ends spans 2 mean widths, so end 0 is 0.5 wide and
    // end 1 is 1.5 wide: end 0 covers u in [0, 0.5), end 1 [0.5, 2), end 2 [2, 2.5), ...
    WovenParams p = matte();
    p.warp_spacing = {1.0f, 3.0f};
    const Weave weave(p);
    struct Case { double e; int64_t thread; double across; };
    const Case cases[] = {
        {0.25, 0, 0.5}, {0.5, 1, 0.0}, {1.25, 1, 0.5}, {1.999, 1, (1.999 - 0.5) / 1.5}, {2.1, 2, 0.2},
        {-0.25, -1, (1.75 - 0.5) / 1.5}, {-2.0, -2, 0.0}, {1e6 + 0.25, 1000000, 0.5},
    };
    for (const Case& c : cases) {
        const ThreadLayout::Cell cell = weave.warp().locate(c.e);
        EXPECT_EQ(cell.thread, c.thread) << c.e;
        EXPECT_NEAR(cell.across, c.across, 1e-9) << c.e;
        EXPECT_EQ(cell.slot, int(((c.thread % 2) + 2) % 2)) << c.e;
    }
    // The weft is untouched: a floor.
    EXPECT_EQ(weave.weft().locate(1.25).thread, 1);
    EXPECT_NEAR(weave.weft().locate(1.25).across, 0.25, 1e-12);

    // In the weave: plain (1,1,1), pick 0. The wide end 1 has the warp on top over u in [0.5, 2).
    p.yarn_width = p.warp_width = 0.5f;  // gaps show where neither yarn is
    const WovenMaterial m(p);
    EXPECT_EQ(yarnAt(m.weave(), p, false, {1.25, 0.5}).type, YarnType::Warp);  // middle of end 1
    EXPECT_EQ(yarnAt(m.weave(), p, false, {1.25, 0.5}).yarnIndex, 1);
    // Across end 1 the warp covers its middle half: u in [0.875, 1.625).
    EXPECT_EQ(yarnAt(m.weave(), p, false, {0.9, 0.5}).type, YarnType::Warp);
    EXPECT_EQ(yarnAt(m.weave(), p, false, {0.85, 0.5}).type, YarnType::Weft);  // the weft below, beside it
    EXPECT_EQ(yarnAt(m.weave(), p, false, {0.85, 0.1}).type, YarnType::Gap);
}

// locate() against a plain search of the cumulative spacing, for a long random sequence whose
// threads range from a tenth to ten times the mean.
TEST(Threads, SpacedLookupMatchesALinearSearch) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> logWidth(-1.0f, 1.0f);
    WovenParams p;
    for (int k = 0; k < 1000; ++k) p.weft_spacing.push_back(std::pow(10.0f, logWidth(rng)));
    const ThreadLayout layout = Weave::threads(p, YarnSide::Weft);
    double total = 0.0;
    for (float s : p.weft_spacing) total += s;
    std::vector<double> start{0.0};
    for (float s : p.weft_spacing) start.push_back(start.back() + s * 1000.0 / total);
    std::uniform_real_distribution<double> where(-3000.0, 3000.0);
    for (int n = 0; n < 20000; ++n) {
        const double e = where(rng);
        const double q = std::floor(e / 1000.0), r = e - q * 1000.0;
        int slot = 0;
        while (start[size_t(slot) + 1] <= r) ++slot;
        const ThreadLayout::Cell cell = layout.locate(e);
        ASSERT_EQ(cell.slot, slot) << e;
        ASSERT_EQ(cell.thread, int64_t(q) * 1000 + slot) << e;
        ASSERT_NEAR(cell.across, (r - start[size_t(slot)]) / (start[size_t(slot) + 1] - start[size_t(slot)]), 1e-6) << e;
    }
}

TEST(Threads, YarnTypesSetTheirFieldsAndFollowTheSideForTheRest) {
    WovenParams p = matte();
    p.ex = 10.0f;
    p.warp_ex = 20.0f;
    p.warp_width = 0.9f;
    YarnSpec shiny;
    shiny.value[kYarnEx] = 300.0f;
    shiny.set[kYarnEx] = true;
    YarnSpec thin;
    thin.value[kYarnWidth] = 0.5f;
    thin.set[kYarnWidth] = true;
    p.yarns = {shiny, thin};
    p.warp_yarns = {0, 1};  // even ends shiny, odd ends thin
    p.weft_yarns = {1};     // every pick thin
    const Weave weave(p);
    // End 0: shiny on the warp: ex 300, the warp's width 0.9. End 1: thin: the warp's ex 20.
    const Yarn& end0 = weave.yarn(weave.warp().yarn(0));
    const Yarn& end1 = weave.yarn(weave.warp().yarn(1));
    const Yarn& pick = weave.yarn(weave.weft().yarn(0));
    EXPECT_EQ(end0.ex(), 300.0f);
    EXPECT_EQ(end0.width(), 0.9f);
    EXPECT_EQ(end1.ex(), 20.0f);
    EXPECT_EQ(end1.width(), 0.5f);
    EXPECT_EQ(pick.ex(), 10.0f);  // thin on the weft: the weft's own ex
    EXPECT_EQ(pick.width(), 0.5f);
    // Widths decide coverage: at cell (1, 0) the warp (end 1, 0.5 wide) is on top; at s = 0.2
    // it does not cover, the weft (0.5 wide) at t = 0.5 does; at t = 0.1 neither does.
    EXPECT_EQ(yarnAt(weave, p, false, {1.2, 0.5}).type, YarnType::Weft);
    EXPECT_EQ(yarnAt(weave, p, false, {1.2, 0.1}).type, YarnType::Gap);
    // End 3 (thin) lets the thin weft show beside it; end 2 (shiny, the warp's 0.9) covers s = 0.1.
    EXPECT_EQ(yarnAt(weave, p, false, {3.1, 0.5}).type, YarnType::Weft);
    EXPECT_EQ(yarnAt(weave, p, false, {2.1, 1.5}).type, YarnType::Warp);
    // Both sides have yarns narrower than 1: see-through gaps are possible.
    EXPECT_TRUE(mayShowGaps(p));
    p.weft_yarns.clear();  // the weft's own width 1 covers every gap
    EXPECT_FALSE(mayShowGaps(p));
}

// MODEL.md section 6: two threads with the same yarn type and colour shade identically, and a
// draft whose threads are all alike shades as the plain material with those values.
TEST(Threads, AlikeThreadsShadeAsThePlainMaterial) {
    WovenParams plain;
    plain.pattern = {1, 2, 1};
    plain.cy = 0.6f;
    plain.warp_color = {0.3f, 0.5f, 0.2f};
    plain.weft_color = {0.6f, 0.1f, 0.4f};
    plain.warp_ex = 250.0f;
    plain.warp_width = 0.8f;
    plain.yarn_width = 0.7f;
    plain.noise = 0.2f;
    plain.crimp = 0.3f;
    WovenParams lists = plain;
    lists.warp_color = lists.weft_color = glm::vec3(0.9f);  // overridden by every thread
    lists.warp_ex = 1.0f;
    lists.warp_width = 1.0f;
    lists.warp_colors.assign(5, plain.warp_color);
    lists.weft_colors.assign(2, plain.weft_color);
    YarnSpec warpYarn;
    warpYarn.value[kYarnEx] = 250.0f;
    warpYarn.value[kYarnWidth] = 0.8f;
    warpYarn.set[kYarnEx] = warpYarn.set[kYarnWidth] = true;
    lists.yarns = {warpYarn};
    lists.warp_yarns = {0, 0, 0};
    const WovenMaterial a(plain), b(lists);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uv(-30.0, 30.0);
    for (int n = 0; n < 2000; ++n) {
        ShadingInput in;
        in.uv = {uv(rng), uv(rng)};
        in.backSide = n % 2 == 1;
        const auto sa = a.shade(in), sb = b.shade(in);
        ASSERT_EQ(sa.has_value(), sb.has_value());
        if (!sa) continue;
        ASSERT_EQ(sa->yarn, sb->yarn);
        const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f)), wi = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.8f));
        ASSERT_EQ(sa->bsdf.eval(wo, wi), sb->bsdf.eval(wo, wi)) << in.uv.x << "," << in.uv.y;
    }
}

TEST(Threads, CoverageByHand) {
    // Plain weave, weft 0.6 wide, warp 0.5: on a weft-top cell the weft covers 0.6 and the warp
    // (1 - 0.6) 0.5 = 0.2; on a warp-top cell the warp 0.5 and the weft 0.5 * 0.6 = 0.3. Half the
    // cells each: weft 0.45, warp 0.35.
    WovenParams p = matte();
    p.yarn_width = 0.6f;
    p.warp_width = 0.5f;
    const WeaveCoverage plain = weaveCoverage(Weave(p), false);
    EXPECT_NEAR(plain.weft, 0.45f, 1e-6f);
    EXPECT_NEAR(plain.warp, 0.35f, 1e-6f);
    // Warp spacing 1 and 3 (cells 0.5 and 1.5 wide), end 1 of a thin yarn type (0.3): the
    // repeat of 2 x 2 cells has area 4. Pick 0 (weft over end 0, under end 1): weft
    // 0.5 x 0.6 + 1.5 x (1 - 0.3) x 0.6 = 0.93, warp 0.5 x 0.4 x 0.5 + 1.5 x 0.3 = 0.55. Pick 1
    // (under end 0, over end 1): weft 0.5 x 0.5 x 0.6 + 1.5 x 0.6 = 1.05, warp
    // 0.5 x 0.5 + 1.5 x 0.4 x 0.3 = 0.43. Together weft 1.98 / 4, warp 0.98 / 4.
    YarnSpec thin;
    thin.value[kYarnWidth] = 0.3f;
    thin.set[kYarnWidth] = true;
    p.yarns = {YarnSpec{}, thin};  // an empty yarn type is the warp's own
    p.warp_yarns = {0, 1};
    p.warp_spacing = {1.0f, 3.0f};
    const WeaveCoverage spaced = weaveCoverage(Weave(p), false);
    EXPECT_NEAR(spaced.weft, 1.98f / 4.0f, 1e-6f);
    EXPECT_NEAR(spaced.warp, 0.98f / 4.0f, 1e-6f);
    // The back of a plain weave is the front shifted by one pick: the same coverage.
    const WeaveCoverage back = weaveCoverage(Weave(p), true);
    EXPECT_NEAR(back.weft, spaced.weft, 1e-6f);
    EXPECT_NEAR(back.warp, spaced.warp, 1e-6f);
}

}  // namespace
}  // namespace woven
