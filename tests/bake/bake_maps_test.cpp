// The baked maps against the model on a flat cloth: the baked textures, read back through the
// renderer's own glTF material (texture transform, sRGB, normal map, anisotropy), at random points
// of the weave, against WovenMaterial::shade() at the same points. Points near a yarn's edge or
// where its normal turns fast are left out: there a texel is an average over the footprint, by
// design. Materials with gaps, per-thread colours and noise; crimp; spacing and yarn types.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "far_field.h"
#include "gltf_material.h"
#include "lobe_fit.h"
#include "woven_bake.h"
#include "woven_material.h"

namespace woven {
namespace {

struct Case {
    const char* name;
    WovenParams params;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
    WovenParams gaps;
    gaps.repeat = {40.0f, 50.0f};
    gaps.yarn_width = 0.7f;
    gaps.warp_width = 0.6f;
    gaps.cy = 0.8f;
    gaps.noise = 0.3f;
    gaps.warp_colors = {{0.7f, 0.1f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.2f, 0.2f, 0.7f}};
    gaps.weft_colors = {{0.8f, 0.8f, 0.2f}, {0.1f, 0.1f, 0.1f}};

    WovenParams satin;
    satin.pattern = {9, 1, 3};
    satin.repeat = {80.0f, 80.0f};
    satin.crimp = 0.6f;
    satin.warp_color = {0.6f, 0.5f, 0.2f};

    WovenParams twill;
    twill.pattern = {1, 2, 1};
    twill.repeat = {60.0f, 60.0f};
    twill.warp_spacing = {1.0f, 1.6f, 0.8f};
    YarnSpec glossy;
    glossy.value[kYarnEx] = 400.0f, glossy.set[kYarnEx] = true;
    glossy.value[kYarnEy] = 8.0f, glossy.set[kYarnEy] = true;
    twill.yarns = {YarnSpec{}, glossy};
    twill.weft_yarns = {0, 1};
    return {{"plain_gaps_thread_colours_noise", gaps}, {"satin_crimp", satin}, {"twill_spacing_yarn_types", twill}};
}

struct ModelPoint {
    std::optional<WovenShading> shading;
    int64_t thread = 0;
};

class BakedMaps : public testing::TestWithParam<Case> {};

TEST_P(BakedMaps, AgreeWithTheModelAtPointsInsideTheYarnsAndGaps) {
    const WovenParams& p = GetParam().params;
    BakeOptions options;
    options.size = 256;
    const BakedMaterial baked = bakeWoven(p, options);
    const WovenMaterial model(p);
    const GltfMaterial gltf(baked.material, baked.textures);
    const glm::dvec2 texel = baked.uvSize / glm::dvec2(baked.textures[0].width, baked.textures[0].height);

    const auto at = [&](glm::dvec2 uv) {
        ShadingInput in;
        in.uv = uv;
        const YarnPoint y = yarnAt(model.weave(), p, false, uv);
        return ModelPoint{model.shade(in), y.yarnIndex * 2 + int(y.type)};
    };
    const auto angle = [](glm::vec3 a, glm::vec3 b) { return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)); };
    const float degree = 3.14159265f / 180.0f;

    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int coverageChecked = 0, coverageWrong = 0, smoothChecked = 0;
    std::vector<float> colourRatios;
    float worstNormal = 0.0f, worstDirection = 0.0f, worstSmooth = 0.0f, worstRough = 0.0f;
    for (int i = 0; i < 6000; ++i) {
        const glm::dvec2 uv = glm::dvec2(u(rng), u(rng)) * baked.uvSize * 3.0;  // three tiles: the texture repeats
        const ModelPoint centre = at(uv);
        // Interior: the same thread (or gap) 1.5 texels away every way; smooth: normals there
        // within 5 degrees of the centre's (a texel's own spread then adds 1 % to alpha at most).
        bool interior = true, smooth = true;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const ModelPoint n = at(uv + 1.5 * texel * glm::dvec2(dx, dy));
                interior = interior && bool(n.shading) == bool(centre.shading) && n.thread == centre.thread;
                if (interior && centre.shading)
                    smooth = smooth && angle(n.shading->bsdf.frame().z, centre.shading->bsdf.frame().z) < 5.0f * degree;
            }
        if (!interior) continue;
        const SurfaceHit hit = flatHit(uv);
        ++coverageChecked;
        coverageWrong += gltf.passesThrough(hit.tex, 0.0f) != !centre.shading;
        if (!centre.shading) continue;

        const Frame& frame = centre.shading->bsdf.frame();
        const AshikhminShirley& lobe = centre.shading->bsdf.lobe();
        const GltfBxdfInputs in = gltf.inputs(hit.tex);
        // Colour noise never repeats: the bake holds the first tile's.
        const bool firstTile = uv.x < baked.uvSize.x && uv.y < baked.uvSize.y;
        for (int c = 0; c < 3 && firstTile; ++c)
            if (lobe.rd()[c] > 0.05f) colourRatios.push_back(in.baseColor[c] / (diffuseScale() * lobe.rd()[c]));
        worstNormal = std::max(worstNormal, angle(gltf.shadingNormal(hit), frame.z));
        if (!smooth) continue;
        ++smoothChecked;
        // The anisotropy direction is the rougher one: across the yarn, in the tangent plane.
        const glm::vec3 direction = gltf.anisotropyDirection(hit);
        const glm::vec2 yarn = glm::normalize(glm::vec2(frame.x));
        worstDirection = std::max(worstDirection, std::abs(glm::dot(glm::normalize(glm::vec2(direction)), yarn)));
        const float alpha = in.roughness * in.roughness;
        const float alphaT = alpha + (1.0f - alpha) * in.anisotropy * in.anisotropy;
        worstSmooth = std::max(worstSmooth, std::abs(alpha / ggxAlphaForExponent(lobe.shape().ex) - 1.0f));
        worstRough = std::max(worstRough, std::abs(alphaT / ggxAlphaForExponent(lobe.shape().ey) - 1.0f));
    }
    std::printf("[ maps ] %s: %d interior points (%d smooth); normal within %.2f deg, direction |cos| %.3f, "
                "alpha along %.1f %%, across %.1f %%\n",
                GetParam().name, coverageChecked, smoothChecked, worstNormal / degree, worstDirection, 100 * worstSmooth, 100 * worstRough);
    ASSERT_GT(smoothChecked, 300);
    ASSERT_GT(colourRatios.size(), 300u);
    // Coverage: every interior point is cut out exactly where the model sees a gap.
    EXPECT_EQ(coverageWrong, 0) << "of " << coverageChecked;
    // Colour: one scale for every point (the far field's fitted scale), up to sRGB's 8 bits
    // (half a step: 0.2 % at mid grey, 1.5 % at 0.08) and the noise changing across the texels
    // that bilinear filtering mixes (1.2 % a texel at noise 0.3): at worst 4.2 % measured with GCC
    // 12 and 5.4 % with clang 14 (which rounds the noise's sums differently), so 6 %.
    std::sort(colourRatios.begin(), colourRatios.end());
    const float median = colourRatios[colourRatios.size() / 2];
    EXPECT_GT(median, 0.6f);
    EXPECT_LT(median, 1.4f);
    EXPECT_LT(colourRatios.front() / median, 1.0f + 0.06f);
    EXPECT_GT(colourRatios.front() / median, 1.0f - 0.06f);
    EXPECT_LT(colourRatios.back() / median, 1.0f + 0.06f);
    // The normal: 8 bits a component (0.3 degree) and bilinear filtering between texels of a
    // turning normal (0.8 degree where it turns fastest among interior points: cy 0.8, 256 texels).
    EXPECT_LT(worstNormal, 1.5f * degree);
    // Direction across the yarn to 8 bits; widths as lobe_fit.h maps the exponents, up to
    // the roughness's 8 bits (1.5 % of alpha at alpha 0.14) and a turning normal's spread.
    EXPECT_LT(worstDirection, 0.02f);
    EXPECT_LT(worstSmooth, 0.05f);
    EXPECT_LT(worstRough, 0.05f);
}

INSTANTIATE_TEST_SUITE_P(Weaves, BakedMaps, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

TEST(Bake, IsAPureFunctionOfItsParameters) {
    WovenParams p = cases()[0].params;
    BakeOptions options;
    options.size = 64;
    const BakedMaterial a = bakeWoven(p, options), b = bakeWoven(p, options);
    for (int map = 0; map < BakedMaterial::kMapCount; ++map) EXPECT_EQ(a.textures[size_t(map)].bytes, b.textures[size_t(map)].bytes);
    EXPECT_EQ(a.material.sheen.color, b.material.sheen.color);
    EXPECT_EQ(a.material.specular, b.material.specular);
}

TEST(Bake, TexturesSpanTheWeavesRepeatAndKeepItsSize) {
    // A twill (3 x 3 threads) with 4 warp colours repeats every 12 x 3 threads; at 60 threads
    // per uv unit, 2 repeats a texture span 0.4 x 0.1 in uv, and the texture is 4 : 1.
    WovenParams p;
    p.pattern = {1, 2, 1};
    p.repeat = {60.0f, 60.0f};
    p.warp_colors = {{0.1f, 0.1f, 0.1f}, {0.9f, 0.9f, 0.9f}, {0.5f, 0.1f, 0.1f}, {0.1f, 0.5f, 0.1f}};
    BakeOptions options;
    options.size = 256;
    options.repeats = 2;
    const BakedMaterial b = bakeWoven(p, options);
    EXPECT_EQ(b.threads, glm::ivec2(12, 3));
    EXPECT_NEAR(b.uvSize.x, 0.4, 1e-9);
    EXPECT_NEAR(b.uvSize.y, 0.1, 1e-9);
    EXPECT_EQ(b.textures[0].width, 256);
    EXPECT_EQ(b.textures[0].height, 64);
    // uv' = uv / uvSize: one texture a tile.
    const glm::vec3 scaled = b.material.baseColorTexture.uvTransform * glm::vec3(0.4f, 0.1f, 1.0f);
    EXPECT_NEAR(scaled.x, 1.0f, 1e-6f);
    EXPECT_NEAR(scaled.y, 1.0f, 1e-6f);
    // Mip levels down to 1 x 1, each half the one above.
    ASSERT_EQ(b.mipLevels.size(), size_t(BakedMaterial::kMapCount));
    EXPECT_EQ(b.mipLevels[0].size(), 8u);
    EXPECT_EQ(b.mipLevels[0][0].width, 128);
    EXPECT_EQ(b.mipLevels[0].back().width, 1);
    EXPECT_EQ(b.mipLevels[0].back().height, 1);
}

TEST(Bake, RefusesARepeatTooLongForItsSize) {
    WovenParams p;
    p.warp_colors.assign(300, glm::vec3(0.5f));
    p.warp_colors[7] = glm::vec3(0.1f);
    BakeOptions options;
    options.size = 512;  // 300 threads: 1.7 texels a thread
    try {
        bakeWoven(p, options);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("300 x 2 threads"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--size"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace woven
