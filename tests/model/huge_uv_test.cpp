// The weave at any uv: the lookup wraps positions by whole repeats of everything it reads (an
// exact fmod), so a huge uv shows the thread the same point of one repeat shows and ordinary uvs
// are untouched; where the uv's own precision cannot place a point within a quarter thread
// (uv_precision.h), shadeFiltered() gives the far field. Issue 21: at uv 1e10 and beyond the
// cloth was black.
#include <gtest/gtest.h>

#include <cmath>

#include "uv_precision.h"
#include "woven_material.h"
#include "yarn_geometry.h"

namespace woven {
namespace {

const glm::vec3 kWo = glm::normalize(glm::vec3(-0.2f, 0.1f, 0.95f)), kWi = glm::normalize(glm::vec3(0.3f, 0.2f, 0.9f));

// Every part of the lookup that has a period: a twill tile, three warp colours, spaced picks,
// crimp, noise and narrow yarns.
WovenParams richParams(glm::vec2 repeat) {
    WovenParams p;
    p.pattern = {1, 3, 1};
    p.repeat = repeat;
    p.yarn_width = 0.8f;
    p.crimp = 0.4f;
    p.noise = 0.3f;
    p.warp_colors = {{0.8f, 0.1f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.1f, 0.1f, 0.8f}};
    p.weft_spacing = {1.0f, 2.0f};
    return p;
}

ShadingInput at(glm::dvec2 uv) {
    ShadingInput in;
    in.uv = uv;
    return in;
}

TEST(HugeUv, WrappingLeavesOrdinaryPositionsAsTheyAre) {
    const Weave weave(richParams({1, 1}));
    // R along u is lcm(4, 3) 2^58 = 3 2^60 and along v lcm(4, 2) 2^60 (the twill's tile is 4 x 4).
    const glm::dvec2 R(0x1p60 * 3, 0x1p62);
    for (double e : {0.0, 0.37, -0.37, 1e6 + 0.25, -1e12 - 0.5, 0x1p32 * 12 - 0.5, 0x1p60 * 3 - 512, -0x1p61})
        EXPECT_EQ(weave.wrapped(glm::dvec2(e, e)), glm::dvec2(e, e));
    EXPECT_EQ(weave.wrapped(glm::dvec2(R.x * 5.0 + 4096, -R.y * 5.0 - 4096)), glm::dvec2(4096, -4096));
    EXPECT_EQ(weave.wrapped(-R * 7.0 - glm::dvec2(0x1p50)), -glm::dvec2(0x1p50));
}

// At repeat 1, e = uv exactly: a point whole repeats of the tile, the layouts and 2^32 threads
// away is the same thread at the same place across it, with the same noise seed, so everything
// but the noise's position along the yarn is equal bit for bit (the noise is off here for the
// colour check).
TEST(HugeUv, PointsWholeRepeatsApartShowTheSameThread) {
    WovenParams p = richParams({1, 1});
    p.noise = 0.0f;
    const WovenMaterial m(p);
    const glm::dvec2 period(0x1p32 * 12, 0x1p32 * 4);
    for (glm::dvec2 base : {glm::dvec2(0.375, 0.625), glm::dvec2(2.125, 1.75), glm::dvec2(3.5, 0.0625)})
        for (double k : {1.0, 7.0, -3.0}) {
            const YarnPoint a = yarnAt(m.weave(), p, false, base), b = yarnAt(m.weave(), p, false, base + k * period);
            EXPECT_EQ(a.type, b.type);
            EXPECT_EQ(a.slot, b.slot);
            EXPECT_EQ(a.yarn, b.yarn);
            EXPECT_EQ(uint32_t(a.yarnIndex), uint32_t(b.yarnIndex));
            EXPECT_EQ(a.normal, b.normal);
            const auto sa = m.shade(at(base)), sb = m.shade(at(base + k * period));
            ASSERT_EQ(sa.has_value(), sb.has_value());
            if (sa) {
                EXPECT_EQ(sa->bsdf.eval(kWo, kWi), sb->bsdf.eval(kWo, kWi));
            }
        }
    // Beyond 2^63 elements, where an unwrapped thread index overflows: a unit normal.
    for (double u : {1e19, 3e30, -1e300}) {
        const YarnPoint y = yarnAt(m.weave(), p, false, glm::dvec2(u, 0.3));
        EXPECT_NEAR(glm::length(y.normal), 1.0f, 1e-5f) << u;
    }
}

// At repeat 100, uv 1e7 + 0.3037 and 1e10 + 0.3037 (a double still places them to 2e-6 uv, 2e-4
// threads) shade as uv 0.3037 does: their products with the repeat round differently, by under
// 1e-6 threads, hence the 1e-3 relative tolerance. Uv 1e20 (a double's values 1.6e4 apart there)
// and 1e30 give the far field, equal to the far field a huge footprint at uv 0.3037 gives.
TEST(HugeUv, LargeUvsShadeAsTheirWrappedPointOrTheFarField) {
    WovenParams p = richParams({100, 100});
    p.noise = 0.0f;  // the noise is seeded by the thread index, which differs
    const WovenMaterial m(p);
    const auto near = m.shade(at({0.3037, 0.3037}));
    ASSERT_TRUE(near);
    const glm::vec3 f0 = near->bsdf.eval(kWo, kWi);
    ASSERT_GT(f0.r + f0.g + f0.b, 0.0f);
    for (double offset : {1e7, 1e10}) {
        const glm::dvec2 uv(offset + 0.3037, offset + 0.3037);
        ASSERT_TRUE(resolvesThreads(uv, resolvedUvLimit<double>(p.repeat))) << offset;
        const auto s = m.shade(at(uv));
        ASSERT_TRUE(s) << offset;
        const glm::vec3 f = s->bsdf.eval(kWo, kWi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], f0[c], 1e-3f * f0[c]) << offset;
    }
    ShadingInput wide = at({0.3037, 0.3037});
    wide.uvSpacing = glm::dvec2(1e6);
    const auto reference = m.shadeFiltered(wide);
    ASSERT_TRUE(reference);
    ASSERT_EQ(reference->lobe().farWeight(), 1.0f);
    const glm::vec3 fFar = reference->eval(kWo, kWi);
    for (double uv : {1e20, 1e30, -1e300}) {
        ShadingInput in = at({uv, uv});
        ASSERT_FALSE(resolvesThreads(in.uv, resolvedUvLimit<double>(p.repeat))) << uv;
        in.uvSpacing = uvSpacing<double>(in.uv);
        const auto s = m.shadeFiltered(in);
        ASSERT_TRUE(s) << uv;
        EXPECT_EQ(s->lobe().farWeight(), 1.0f);
        const glm::vec3 f = s->eval(kWo, kWi);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(f[c], 0.0f) << uv;
            EXPECT_NEAR(f[c], fFar[c], 1e-4f * fFar[c]) << uv;
        }
    }
}

// A mesh's float uv: from 0.25 / (2^-23 x 100) = 2.1e4 on, the far field fades in.
TEST(HugeUv, FloatUvsStopResolvingThreadsWhereTheirSpacingPassesAQuarterThread) {
    const glm::dvec2 limit = resolvedUvLimit<float>({100, 100});
    EXPECT_NEAR(limit.x, 0.25 / (100 * 0x1p-23), 1e-6);
    EXPECT_TRUE(resolvesThreads({2e4, -2e4}, limit));
    EXPECT_FALSE(resolvesThreads({2e4, 3e4}, limit));
    EXPECT_NEAR(uvSpacing<float>({1e10, 0.0}).x * 100, 1e12 * 0x1p-23, 1.0);
}

}  // namespace
}  // namespace woven
