// Yarn geometry (MODEL.md section 2) and the shading frame of the woven material (section 3):
// cross-section normals, crossing yarns and true gaps, crimp, back face, per-yarn noise, and
// frames from degenerate differential geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "reference_brdf.h"
#include "woven_material.h"
#include "yarn_geometry.h"
#include "yarn_noise.h"

namespace woven {
namespace {

using test::kPi;

void expectNear(const glm::vec3& a, const glm::dvec3& b, double tol, const std::string& what) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

void expectOrthonormal(const Frame& f, const std::string& what) {
    EXPECT_NEAR(glm::length(f.x), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::length(f.y), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::length(f.z), 1.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(f.x, f.y), 0.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(f.x, f.z), 0.0f, 1e-5f) << what;
    EXPECT_NEAR(glm::dot(f.y, f.z), 0.0f, 1e-5f) << what;
}

TEST(YarnGeometry, CrossSectionNormalIsTheFiniteForm) {
    for (float cy : {0.0f, 0.25f, 0.5f, 1.0f})
        for (int n = -1000; n <= 1000; ++n) {
            const float x = n / 1000.0f;
            const glm::vec2 got = crossSectionNormal(cy, x);
            const glm::dvec2 expected =
                glm::normalize(glm::dvec2(double(cy) * x, std::sqrt(std::max(0.0, 1.0 - double(x) * x))));
            ASSERT_TRUE(std::isfinite(got.x) && std::isfinite(got.y)) << cy << " " << x;
            if (cy == 0.0f && std::fabs(x) == 1.0f) continue;  // 0/0, checked below
            ASSERT_NEAR(got.x, expected.x, 1e-5) << "cy=" << cy << " x=" << x;
            ASSERT_NEAR(got.y, expected.y, 1e-5) << "cy=" << cy << " x=" << x;
        }
    // c_y = 1 at the yarn edge: the normal lies in the surface plane (a hard case, MODEL.md 5).
    EXPECT_NEAR(crossSectionNormal(1.0f, 1.0f).x, 1.0f, 1e-6f);
    EXPECT_NEAR(crossSectionNormal(1.0f, 1.0f).y, 0.0f, 1e-6f);
    EXPECT_NEAR(crossSectionNormal(1.0f, -1.0f).x, -1.0f, 1e-6f);
    // c_y = 0: flat, straight up even at the edge.
    EXPECT_EQ(crossSectionNormal(0.0f, 1.0f), glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(crossSectionNormal(0.0f, -1.0f), glm::vec2(0.0f, 1.0f));
    // Just past the edge (float rounding of x) stays finite.
    const glm::vec2 past = crossSectionNormal(1.0f, 1.0000001f);
    EXPECT_TRUE(std::isfinite(past.x) && std::isfinite(past.y));
}

TEST(YarnGeometry, BumpedNormalAcrossWeftAndWarp) {
    WovenParams p;
    p.pattern = {1, 1, 1};
    p.cy = 0.7f;
    const Weave weave(p);
    // Element (0, 0) is weft (across = t, along v), element (1, 0) warp (across = s, along u).
    for (double c = 0.0; c < 1.0; c += 0.05) {
        const double x = (c - 0.5) / 0.5;
        const glm::dvec2 section = glm::normalize(glm::dvec2(0.7 * x, std::sqrt(1.0 - x * x)));
        const YarnPoint weft = yarnAt(weave, p, false, {0.37, c});
        ASSERT_EQ(weft.type, YarnType::Weft);
        EXPECT_EQ(weft.yarnIndex, 0);
        expectNear(weft.normal, {0.0, section.x, section.y}, 1e-5, "weft t=" + std::to_string(c));
        const YarnPoint warp = yarnAt(weave, p, false, {1.0 + c, 0.61});
        ASSERT_EQ(warp.type, YarnType::Warp);
        EXPECT_EQ(warp.yarnIndex, 1);
        expectNear(warp.normal, {section.x, 0.0, section.y}, 1e-5, "warp s=" + std::to_string(c));
    }
    // Repeat: 4 elements per unit u, 2 per unit v. Plain weave: (U, V) = (2, 1) has d = 1, warp;
    // (3, 1) has d = 0, weft.
    p.repeat = {4.0f, 2.0f};
    EXPECT_EQ(yarnAt(weave, p, false, {2.5 / 4.0, 1.5 / 2.0}).type, YarnType::Warp);
    EXPECT_EQ(yarnAt(weave, p, false, {3.5 / 4.0, 1.5 / 2.0}).type, YarnType::Weft);
    EXPECT_EQ(yarnAt(weave, p, false, {3.5 / 4.0, 1.5 / 2.0}).yarnIndex, 1);
}

TEST(YarnGeometry, CrossingYarnInTheGapsAndTrueGaps) {
    WovenParams p;
    p.pattern = {1, 1, 1};
    p.cy = 0.0f;
    p.yarn_width = 0.6f;   // weft covers t in [0.2, 0.8]
    p.warp_width = 0.5f;   // warp covers s in [0.25, 0.75]
    const Weave weave(p);
    // Element (0, 0): weft on top.
    EXPECT_EQ(yarnAt(weave, p, false, {0.1, 0.5}).type, YarnType::Weft);   // beside the warp, on the weft
    EXPECT_EQ(yarnAt(weave, p, false, {0.5, 0.9}).type, YarnType::Warp);   // gap beside the weft: warp below
    EXPECT_EQ(yarnAt(weave, p, false, {0.5, 0.9}).yarnIndex, 0);
    EXPECT_EQ(yarnAt(weave, p, false, {0.9, 0.9}).type, YarnType::Gap);    // neither yarn
    EXPECT_EQ(yarnAt(weave, p, false, {0.1, 0.1}).type, YarnType::Gap);
    // Element (1, 0): warp on top; weft visible beside it, gap at the corners.
    EXPECT_EQ(yarnAt(weave, p, false, {1.5, 0.1}).type, YarnType::Warp);
    EXPECT_EQ(yarnAt(weave, p, false, {1.1, 0.5}).type, YarnType::Weft);
    EXPECT_EQ(yarnAt(weave, p, false, {1.1, 0.9}).type, YarnType::Gap);

    // Coverage: the fraction of gap area is (1 - 0.6)(1 - 0.5) = 0.2 on a fine grid.
    int gaps = 0, total = 0;
    for (int a = 0; a < 200; ++a)
        for (int b = 0; b < 200; ++b, ++total)
            gaps += yarnAt(weave, p, false, {(a + 0.5) / 100.0, (b + 0.5) / 100.0}).type == YarnType::Gap;
    EXPECT_NEAR(double(gaps) / total, 0.2, 0.01);

    // A see-through gap: the material returns no BSDF and the ray filter says so; both faces agree.
    const WovenMaterial see(p);
    ShadingInput in;
    in.uv = {0.9, 0.9};
    EXPECT_FALSE(see.shade(in).has_value());
    in.backSide = true;
    EXPECT_FALSE(see.shade(in).has_value());
    EXPECT_TRUE(see.isSeeThrough({0.9, 0.9}));
    EXPECT_FALSE(see.isSeeThrough({0.5, 0.9}));
    in.uv = {0.5, 0.9};
    ASSERT_TRUE(see.shade(in).has_value());
    EXPECT_EQ(see.shade(in)->yarn, YarnType::Warp);

    // With a backing colour the gap is opaque and shows that colour (diffuse term at normal
    // incidence: 28 / (23 pi) R_d (1 - (1/2)^5)^2, MODEL.md section 4; rs = 0 leaves F(1) = 0).
    p.backing = 1;
    p.backing_color = {0.2f, 0.4f, 0.8f};
    const WovenMaterial backed(p);
    EXPECT_FALSE(backed.isSeeThrough({0.9, 0.9}));
    in.uv = {0.9, 0.9};
    in.backSide = false;
    const auto gap = backed.shade(in);
    ASSERT_TRUE(gap.has_value());
    EXPECT_EQ(gap->yarn, YarnType::Gap);
    const glm::vec3 n = gap->bsdf.shadingNormal();
    const glm::vec3 f = gap->bsdf.eval(n, n);
    const double k = 28.0 / (23.0 * kPi) * std::pow(1.0 - 1.0 / 32.0, 2.0);
    expectNear(f, glm::dvec3(0.2, 0.4, 0.8) * k, 1e-4, "backing colour");

    // Only one width below 1: the other yarn covers every gap, nothing is see-through.
    p.backing = 0;
    p.warp_width = 1.0f;
    const WovenMaterial closed(p);
    for (int a = 0; a < 100; ++a)
        for (int b = 0; b < 100; ++b) {
            const glm::dvec2 uv((a + 0.5) / 50.0, (b + 0.5) / 50.0);
            ASSERT_FALSE(closed.isSeeThrough(uv));
            ASSERT_NE(yarnAt(closed.weave(), p, false, uv).type, YarnType::Gap);
        }
}

TEST(YarnGeometry, CrimpBulgesLongFloatsOnly) {
    WovenParams p;
    p.cy = 0.0f;
    p.crimp = 1.0f;
    WovenParams flat = p;
    flat.crimp = 0.0f;
    // Plain weave: floats of one element stay flat whatever the crimp.
    p.pattern = flat.pattern = {1, 1, 1};
    const Weave plain(p);
    for (double s = 0.02; s < 2.0; s += 0.05) {
        const glm::vec3 a = yarnAt(plain, p, false, {s, 0.5}).normal, b = yarnAt(plain, flat, false, {s, 0.5}).normal;
        EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-6f) << s;
    }
    // Satin (9, 1, 3), row 0: a weft float over U = 0..8. The yarn rises from its first crossing,
    // so the normal leans back (-u) in the first half and forward (+u) in the second, mirror
    // symmetric about the middle (u = 4.5), where it is straight up.
    p.pattern = flat.pattern = {9, 1, 3};
    const Weave satin(p);
    EXPECT_NEAR(yarnAt(satin, p, false, {4.5, 0.5}).normal.x, 0.0f, 1e-5f);
    for (double d = 0.25; d < 4.5; d += 0.5) {
        const glm::vec3 before = yarnAt(satin, p, false, {4.5 - d, 0.5}).normal;
        const glm::vec3 after = yarnAt(satin, p, false, {4.5 + d, 0.5}).normal;
        EXPECT_LT(before.x, 0.0f) << d;
        EXPECT_GT(after.x, 0.0f) << d;
        EXPECT_NEAR(before.x, -after.x, 1e-5f) << d;
        EXPECT_NEAR(glm::length(before), 1.0f, 1e-5f);
        EXPECT_NEAR(yarnAt(satin, flat, false, {4.5 - d, 0.5}).normal.x, 0.0f, 1e-6f);
    }
    // Continuous along the float (no jump at element boundaries inside it).
    for (int U = 1; U < 9; ++U) {
        const glm::vec3 a = yarnAt(satin, p, false, {U - 1e-7, 0.5}).normal, b = yarnAt(satin, p, false, {U + 1e-7, 0.5}).normal;
        EXPECT_NEAR(glm::length(a - b), 0.0f, 1e-4f) << U;
    }
}

TEST(WovenMaterial, AlternatingAxesAndBumpedFrames) {
    WovenParams p;
    p.pattern = {1, 1, 1};
    p.cy = 1.0f;
    const WovenMaterial m(p);
    // A tilted mesh: ns not along z, dp/du not orthogonal to ns, dp/dv skewed.
    const glm::vec3 ns = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
    const glm::vec3 dpdu(2.0f, 0.5f, 0.1f), dpdv(-0.3f, 1.5f, 0.4f);
    // Independent tangent frame: Gram-Schmidt of (dp/du, dp/dv) against ns.
    const glm::dvec3 n(ns);
    const glm::dvec3 t = glm::normalize(glm::dvec3(dpdu) - glm::dot(glm::dvec3(dpdu), n) * n);
    glm::dvec3 b = glm::dvec3(dpdv) - glm::dot(glm::dvec3(dpdv), n) * n;
    b = glm::normalize(b - glm::dot(b, t) * t);
    for (double c = 0.05; c < 1.0; c += 0.1) {
        const double x = (c - 0.5) / 0.5;
        const glm::dvec2 sec = glm::normalize(glm::dvec2(x, std::sqrt(1.0 - x * x)));
        ShadingInput in;
        in.ns = ns;
        in.dpdu = dpdu;
        in.dpdv = dpdv;
        // Weft element (0, 0), across = t (v): the normal turns towards +v.
        in.uv = {0.4, c};
        auto weft = m.shade(in);
        ASSERT_TRUE(weft.has_value());
        EXPECT_EQ(weft->yarn, YarnType::Weft);
        const glm::dvec3 weftNormal = sec.x * b + sec.y * n;
        expectNear(weft->bsdf.frame().z, weftNormal, 1e-4, "weft normal");
        expectNear(weft->bsdf.frame().x, t, 1e-4, "weft axis along u");  // the bump turns about u
        expectOrthonormal(weft->bsdf.frame(), "weft");
        // Warp element (1, 0), across = s (u): the normal turns towards +u; lobe x along v.
        in.uv = {1.0 + c, 0.4};
        auto warp = m.shade(in);
        ASSERT_TRUE(warp.has_value());
        EXPECT_EQ(warp->yarn, YarnType::Warp);
        const glm::dvec3 warpNormal = sec.x * t + sec.y * n;
        expectNear(warp->bsdf.frame().z, warpNormal, 1e-4, "warp normal");
        expectNear(warp->bsdf.frame().x, b, 1e-4, "warp axis along v");
        expectOrthonormal(warp->bsdf.frame(), "warp");
    }
}

TEST(WovenMaterial, BackSideSeesTheOtherYarnAndTheOtherNormal) {
    WovenParams p;
    p.pattern = {9, 1, 3};
    p.cy = 0.5f;
    const WovenMaterial m(p);
    for (int U = 0; U < 10; ++U)
        for (int V = 0; V < 10; ++V) {
            ShadingInput in;
            in.uv = {U + 0.5, V + 0.5};
            const auto front = m.shade(in);
            in.backSide = true;
            const auto back = m.shade(in);
            ASSERT_TRUE(front && back);
            EXPECT_NE(front->yarn, back->yarn) << U << "," << V;
            EXPECT_GT(front->bsdf.shadingNormal().z, 0.99f);
            EXPECT_LT(back->bsdf.shadingNormal().z, -0.99f);
        }
}

TEST(WovenMaterial, DegenerateTangentsGiveOrthonormalFrames) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, 0.1f, -0.9f));
    const glm::vec3 zero(0.0f), nan(std::nanf("")), inf(INFINITY, 0.0f, 0.0f);
    const glm::vec3 dpdvs[] = {glm::vec3(0.0f, 1.0f, 0.0f), zero, n * 3.0f, nan};
    const glm::vec3 dpdus[] = {zero, n * 2.0f, nan, inf, glm::vec3(1e-20f, 0.0f, 0.0f)};
    for (const glm::vec3& du : dpdus)
        for (const glm::vec3& dv : dpdvs) {
            const Frame f = tangentFrame(n, du, dv);
            expectOrthonormal(f, "degenerate dp/du");
            EXPECT_NEAR(glm::length(f.z - n), 0.0f, 1e-6f);
        }
    // dp/du = 0 but dp/dv usable: the frame keeps +v along dp/dv.
    const Frame f = tangentFrame(glm::vec3(0, 0, 1), zero, glm::vec3(0.0f, 2.0f, 0.0f));
    EXPECT_NEAR(f.y.y, 1.0f, 1e-6f);
    EXPECT_NEAR(std::fabs(f.x.x), 1.0f, 1e-6f);
}

TEST(YarnNoise, ContinuousAlongAYarnIndependentBetweenYarns) {
    // Continuity: 1D Perlin noise with gradients in [-1, 1] and the quintic fade has slope
    // below 2 * 1.9 (the output is doubled), so a step of 1e-4 moves it by less than 1e-3.
    for (uint32_t seed = 0; seed < 50; ++seed)
        for (double a = -20.0; a < 20.0; a += 0.01) {
            const float n0 = yarnNoise(a, seed), n1 = yarnNoise(a + 1e-4, seed);
            ASSERT_TRUE(std::isfinite(n0));
            ASSERT_LE(std::fabs(n0), 1.0f);
            ASSERT_LT(std::fabs(n1 - n0), 1e-3f) << seed << " " << a;
        }
    // Independence: the correlation of neighbouring seeds over a long stretch is small
    // (for 2000 roughly independent features its standard error is about 0.02).
    for (uint32_t seed = 0; seed < 10; ++seed) {
        double sab = 0, saa = 0, sbb = 0;
        for (double a = 0.0; a < 2000.0; a += 0.25) {
            const double x = yarnNoise(a, seed), y = yarnNoise(a, seed + 1);
            sab += x * y;
            saa += x * x;
            sbb += y * y;
        }
        EXPECT_LT(std::fabs(sab / std::sqrt(saa * sbb)), 0.1) << seed;
        EXPECT_GT(saa, 0.0);
    }
}

TEST(WovenMaterial, NoiseChangesColourPerYarnSmoothlyAlongIt) {
    WovenParams p;
    p.pattern = {1, 0, 0};  // all weft: one yarn per row
    p.cy = 0.0f;
    p.rs = 0.0f;
    p.weft_color = {0.5f, 0.5f, 0.5f};
    p.noise = 0.5f;
    const WovenMaterial noisy(p);
    p.noise = 0.0f;
    const WovenMaterial clean(p);
    const glm::vec3 up(0, 0, 1);
    auto red = [&](const WovenMaterial& m, double u, double v) {
        ShadingInput in;
        in.uv = {u, v};
        return m.shade(in)->bsdf.eval(up, up).r;
    };
    const float base = red(clean, 0.3, 0.5);
    int differsFromBase = 0, differsBetweenRows = 0;
    for (int i = 0; i < 200; ++i) {
        const double u = 0.37 * i;
        EXPECT_FLOAT_EQ(red(clean, u, 0.5), base);
        differsFromBase += std::fabs(red(noisy, u, 0.5) - base) > 1e-3f * base;
        differsBetweenRows += std::fabs(red(noisy, u, 0.5) - red(noisy, u, 1.5)) > 1e-3f * base;
        // Continuous along the yarn, also across element boundaries (u integer).
        EXPECT_NEAR(red(noisy, std::floor(u) + 1 - 1e-6, 0.5), red(noisy, std::floor(u) + 1 + 1e-6, 0.5),
                    1e-3f * base);
        // The same yarn at another v inside its row has the same colour.
        EXPECT_FLOAT_EQ(red(noisy, u, 0.2), red(noisy, u, 0.8));
    }
    EXPECT_GT(differsFromBase, 150);
    EXPECT_GT(differsBetweenRows, 150);
}

}  // namespace
}  // namespace woven
