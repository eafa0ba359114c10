// The GLSL twin against core: the preview's direct-lighting image of a flat cloth, compared
// pixel by pixel with WovenMaterial::shade + SurfaceBsdf::eval evaluated on the CPU for the
// same camera rays and lights.
#include <gtest/gtest.h>

#include <iostream>

#include "flat_cloth.h"
#include "gl_test_context.h"
#include "image_error.h"
#include "material_json.h"

namespace woven::test {
namespace {

constexpr int kWidth = 256, kHeight = 192;

struct NamedParams {
    const char* name;
    WovenParams params;
    // Vertex normals facing away from their triangles' winding, as a fold seen edge-on has them:
    // core shows the winding side, the vertex normal turned to it (SurfaceHit::nsFlipped), and so
    // must the preview. It showed the side the vertex normal faced, the back's weave: a 3/1
    // twill's white weft where core shows its blue warp (mean relative error 2.4 so).
    bool normalsAgainstWinding = false;
};
void PrintTo(const NamedParams& p, std::ostream* os) { *os << p.name; }

std::vector<NamedParams> nearFieldCases() {
    // Repeat 12: elements span 8 or more pixels everywhere in the image, so the weave filter
    // stays off and the shader point-samples the model exactly as the CPU does.
    WovenParams plain;
    plain.repeat = glm::vec2(12.0f);

    WovenParams twill;
    twill.pattern = {1, 2, 1};
    twill.repeat = glm::vec2(12.0f);
    twill.warp_ex = 300.0f;
    twill.warp_ey = 8.0f;
    twill.weft_color = {0.2f, 0.3f, 0.6f};
    twill.warp_color = {0.7f, 0.6f, 0.3f};
    twill.noise = 0.4f;
    twill.noise_scale = 0.7f;
    twill.crimp = 0.5f;
    twill.yarn_width = 0.8f;  // both narrower: see-through gaps
    twill.warp_width = 0.7f;

    WovenParams satin;
    satin.pattern = {9, 1, 3};
    satin.repeat = glm::vec2(14.0f, 12.0f);
    satin.cy = 1.0f;  // circular yarns: the bumped normal reaches the surface plane at the edge
    satin.crimp = 0.8f;
    satin.ex = 2000.0f;
    satin.ey = 1.0f;
    satin.rs = 0.1f;
    satin.yarn_width = 0.85f;
    satin.warp_width = 0.9f;
    satin.backing = 1;
    satin.backing_color = {0.05f, 0.3f, 0.05f};

    WovenParams herringbone;
    herringbone.tile = {"--||", "-||-", "||--", "|--|", "||--", "-||-"};
    herringbone.repeat = glm::vec2(12.0f);
    herringbone.cy = 0.8f;
    herringbone.ex = 50.0f;
    herringbone.ey = 10.0f;
    herringbone.warp_ex = 500.0f;
    herringbone.warp_ey = 0.0f;
    herringbone.noise = 0.3f;
    // A WIF material: the 2/2 twill with thicker, wider-spaced stripes of assets/drafts (per-end
    // colours, uneven warp spacing, yarn types of two widths), with crimp, noise and a bump.
    std::vector<std::string> warnings;
    WovenParams wif = materialFromJson({{"wif", std::string(WOVEN_ASSETS_DIR) + "/drafts/twill_stripes.wif"},
                                        {"repeat", {9, 12}}, {"cy", 0.7}, {"crimp", 0.5}, {"noise", 0.3}},
                                       WovenParams{}, "", warnings).params;

    // Everything per thread at once: uneven spacing both ways, yarn types that differ in every
    // field, colours, see-through gaps and a float tile.
    WovenParams threads;
    threads.pattern = {3, 1, 1};
    threads.repeat = glm::vec2(10.0f);
    threads.crimp = 0.6f;
    threads.warp_colors = {{0.8f, 0.1f, 0.1f}, {0.1f, 0.6f, 0.2f}, {0.9f, 0.9f, 0.8f}};
    threads.weft_colors = {{0.1f, 0.1f, 0.5f}, {0.7f, 0.5f, 0.1f}};
    YarnSpec glossy, thin;
    glossy.value = {800.0f, 5.0f, 0.2f, 0.95f, 1.0f, 0.0f};
    glossy.set.fill(true);
    thin.value[kYarnWidth] = 0.6f;
    thin.value[kYarnNoise] = 0.5f;
    thin.set[kYarnWidth] = thin.set[kYarnNoise] = true;
    threads.yarns = {glossy, thin};
    threads.warp_yarns = {0, 1, 1, 0};
    threads.weft_yarns = {1, 0};
    threads.warp_spacing = {1.0f, 2.0f, 0.7f};
    threads.weft_spacing = {1.5f, 1.0f, 0.5f, 1.0f};
    WovenParams denimLike;
    denimLike.pattern = {3, 1, 1};
    denimLike.repeat = glm::vec2(12.0f);
    denimLike.warp_color = {0.1f, 0.15f, 0.5f};
    denimLike.weft_color = {0.9f, 0.9f, 0.85f};

    return {{"plain", plain},          {"twill_noise_crimp_gaps", twill}, {"satin_backing", satin},
            {"herringbone_tile", herringbone}, {"wif_twill_stripes", wif}, {"threads_spaced_yarns", threads},
            {"normals_against_winding", denimLike, true}};
}

class GlslVsCore : public testing::TestWithParam<NamedParams> {};

TEST_P(GlslVsCore, DirectLightingMatchesCoreWithinBounds) {
    SceneDescription scene = flatClothScene(GetParam().params);
    if (GetParam().normalsAgainstWinding)
        for (glm::vec3& n : scene.meshes[0].normals) n = -n;
    // A background no lit yarn has, to tell where each image sees through the cloth.
    scene.environment.color = glm::vec3(0.3f, 0.0f, 0.3f);
    const Image gpu = previewRadiance(scene, kWidth, kHeight, true, false);
    std::vector<uint8_t> onYarn;
    const Image cpu = coreDirectLighting(scene, kWidth, kHeight, 1, &onYarn);

    const ImageError e = relativeError(gpu, cpu, onYarn);
    std::cout << GetParam().name << ": " << e.pixels << " yarn pixels, mean relative error " << e.mean
              << ", 99th percentile " << e.p99 << "\n";
    ASSERT_GT(e.pixels, size_t(kWidth * kHeight / 4));
    // Both evaluate the same formulas in single precision at the same points, so what differs
    // is float rounding in a different order of operations: measured on llvmpipe, mean 5e-6 to
    // 6e-6 and 99th percentile 7e-5 to 1.3e-4. The bounds leave 20x and 40x room for another
    // GPU's transcendental functions; one wrong sign in the crimp gives a mean of 0.35.
    EXPECT_LT(e.mean, 1e-4);
    EXPECT_LT(e.p99, 5e-3);

    // See-through gaps and the cloth's outline: the preview shows the background exactly where
    // core's ray passes, but for pixels centred within rounding of an edge.
    size_t coverageMismatch = 0, onCloth = 0;
    for (size_t i = 0; i < onYarn.size(); ++i) {
        const bool gpuCovered = gpu.pixels[i] != scene.environment.color;
        coverageMismatch += gpuCovered != (onYarn[i] != 0);
        onCloth += onYarn[i];
    }
    std::cout << "  coverage differs in " << coverageMismatch << " of " << onCloth << " pixels\n";
    EXPECT_LT(double(coverageMismatch), 0.002 * double(onCloth));
}

INSTANTIATE_TEST_SUITE_P(Presets, GlslVsCore, testing::ValuesIn(nearFieldCases()),
                         [](const testing::TestParamInfo<NamedParams>& info) { return std::string(info.param.name); });

// A glTF material made woven (Material::keptSurface): an sRGB base colour texture printed on
// noisy twill yarns, its normal map under the weave's bump, and MASK alpha cutting one texel out.
// The normal map is magnified NEAREST: the yarns' sharp highlights turn the GPU's fixed-point
// bilinear weights into a 99th percentile of 3.4e-2 (1.5e-3 mean, 2e-3 p99 without it).
TEST(GlslVsCore, KeptGltfSurfacePrintNormalMapAndAlphaMatchCore) {
    Material m;
    WovenParams& p = m.woven.emplace();
    p.pattern = {1, 2, 1};
    p.repeat = glm::vec2(12.0f);
    p.cy = 0.6f;
    p.noise = 0.3f;
    p.weft_color = p.warp_color = glm::vec3(0.9f, 0.8f, 0.7f);
    m.keptSurface = KeptGltfSurface{};
    m.baseColorTexture.image = 0;
    m.baseColorTexture.srgb = true;
    m.normalTexture.image = 1;
    m.normalTexture.scale = 0.7f;
    m.normalTexture.nearest = true;
    m.alphaMode = AlphaMode::Mask;
    SceneDescription scene = flatScene(m);
    scene.textures = {
        texture4x4([](int x, int y) {
            const glm::u8vec4 c = (x + y) % 2 ? glm::u8vec4(230, 90, 40, 255) : glm::u8vec4(60, 140, 230, 255);
            return x == 1 && y == 2 ? glm::u8vec4(c.r, c.g, c.b, 0) : c;
        }),
        texture4x4([](int x, int y) { return glm::u8vec4(128 + 25 * (x - 2), 128 - 20 * (y - 2), 230, 255); }),
    };
    scene.environment.color = glm::vec3(0.3f, 0.0f, 0.3f);
    const Image gpu = previewRadiance(scene, kWidth, kHeight, true, false);
    std::vector<uint8_t> onYarn;
    const Image cpu = coreDirectLighting(scene, kWidth, kHeight, 1, &onYarn);
    const ImageError e = relativeError(gpu, cpu, onYarn);
    std::cout << "kept glTF surface: " << e.pixels << " yarn pixels, mean relative error " << e.mean
              << ", 99th percentile " << e.p99 << "\n";
    ASSERT_GT(e.pixels, size_t(kWidth * kHeight / 4));
    // The print adds the GPU's fixed-point filtering after an sRGB table lookup, as for the glTF
    // material (gltf_glsl_vs_core_test.cpp): measured on llvmpipe, mean 1.5e-3, 99th percentile
    // 2e-3. The bounds leave 3x and 5x room; the print left out or not sRGB-decoded, or the
    // normal map's bitangent flipped, gives tens of per cent.
    EXPECT_LT(e.mean, 5e-3);
    EXPECT_LT(e.p99, 1e-2);
    size_t coverageMismatch = 0, onCloth = 0;
    for (size_t i = 0; i < onYarn.size(); ++i) {
        coverageMismatch += (gpu.pixels[i] != scene.environment.color) != (onYarn[i] != 0);
        onCloth += onYarn[i];
    }
    std::cout << "  coverage differs in " << coverageMismatch << " of " << onCloth << " pixels\n";
    EXPECT_LT(double(coverageMismatch), 0.002 * double(onCloth));
}

// Light through the yarns (docs/MODEL_TRANSMISSION.md): a gap-free satin whose faces differ
// (warp-faced front, weft-faced back, other colours, round yarns) passes the light of the lamps
// behind it, seen from its front and from its back. Core's image is SceneMaterials::bsdf +
// Bsdf::eval over every light, the ones behind through the transmitting BSDF with the cosine the
// integrators take.
TEST(GlslVsCore, DirectLightThroughTheSheetMatchesCore) {
    WovenParams p;
    p.pattern = {5, 1, 2};
    p.repeat = glm::vec2(12.0f);
    p.warp_color = {0.7f, 0.55f, 0.3f};
    p.weft_color = {0.3f, 0.4f, 0.65f};
    p.cy = 0.8f;
    p.noise = 0.2f;
    p.transmission = 0.9f;
    p.transmission_gloss = 0.5f;
    for (bool fromBehind : {false, true}) {
        SceneDescription scene = flatClothScene(p);
        PunctualLight under;  // behind the cloth seen from above, in front of it seen from below
        under.type = PunctualLight::Type::Point;
        under.position = {0.4f, -1.2f, -0.3f};
        under.intensity = glm::vec3(2.5f, 2.2f, 2.0f);
        scene.lights.push_back(under);
        if (fromBehind) {
            // Mirrored below the cloth (y -> -y), its x axis turned to stay right-handed.
            glm::mat4& m = scene.camera.cameraToWorld;
            for (int c = 0; c < 4; ++c) m[c][1] = -m[c][1];
            m[0] = -m[0];
        }
        scene.environment.color = glm::vec3(0.3f, 0.0f, 0.3f);
        const Image gpu = previewRadiance(scene, kWidth, kHeight, true, false);
        std::vector<uint8_t> onYarn;
        const Image cpu = coreDirectLighting(scene, kWidth, kHeight, 1, &onYarn);
        const ImageError e = relativeError(gpu, cpu, onYarn);
        // What transmission adds, so the test is seen to test it: core's image without it.
        WovenParams opaque = p;
        opaque.transmission = 0.0f;
        SceneDescription opaqueScene = scene;
        opaqueScene.materials[0].woven = opaque;
        const ImageError added = relativeError(coreDirectLighting(opaqueScene, kWidth, kHeight, 1, nullptr), cpu, onYarn);
        std::cout << (fromBehind ? "back" : "front") << ": " << e.pixels << " yarn pixels, mean relative error " << e.mean
                  << ", 99th percentile " << e.p99 << "; without transmission core differs by " << added.mean << "\n";
        ASSERT_GT(e.pixels, size_t(kWidth * kHeight / 4));
        EXPECT_GT(added.mean, 0.1);
        // The issue asks for 2 % on direct light; both evaluate the same formulas in single
        // precision, so what is left is float rounding, as in the reflection-only cases above:
        // measured on llvmpipe, mean 7e-6 (front) and 4e-6 (back), 99th percentile 1.4e-4 and
        // 5e-5; the same bounds as theirs. The cosine about the seen yarn's normal instead of the
        // transmission's gives a mean of 0.03 seen from the front and 0.2 from the back.
        EXPECT_LT(e.mean, 1e-4);
        EXPECT_LT(e.p99, 5e-3);
    }
}

}  // namespace
}  // namespace woven::test

namespace woven::test {
namespace {

// Far away the weave is finer than the pixels: a point-sampled shader aliases (moire), the
// filtered one must approach the pixel's true mean, here core's image averaged over 16 x 16
// sub-pixel positions.
// The filtered and the point-sampled preview of `p`'s flat cloth at 128 x 96, each against core's
// image averaged over 16 x 16 sub-pixel positions; printed as `what`.
struct FarFieldErrors {
    ImageError filtered, pointSampled;
};
FarFieldErrors farFieldErrors(const WovenParams& p, const char* what) {
    const SceneDescription scene = flatClothScene(p);
    const int w = 128, h = 96;
    std::vector<uint8_t> onCloth;
    const Image reference = coreDirectLighting(scene, w, h, 16, &onCloth);
    const FarFieldErrors e{relativeError(previewRadiance(scene, w, h, true, false), reference, onCloth),
                           relativeError(previewRadiance(scene, w, h, false, false), reference, onCloth)};
    std::cout << what << ", " << e.filtered.pixels << " pixels: filtered mean " << e.filtered.mean << " p99 "
              << e.filtered.p99 << "; point-sampled mean " << e.pointSampled.mean << " p99 " << e.pointSampled.p99
              << "\n";
    return e;
}

TEST(WeaveFilter, DistantClothApproachesCoresPixelAverage) {
    WovenParams p;
    p.pattern = {1, 2, 1};
    p.repeat = glm::vec2(400.0f);  // 3.5 or more elements per pixel at 128 x 96
    p.cy = 0.7f;
    p.ex = 200.0f;
    p.ey = 4.0f;
    p.weft_color = {0.2f, 0.3f, 0.6f};
    p.warp_color = {0.7f, 0.6f, 0.3f};
    p.yarn_width = 0.9f;
    p.warp_width = 0.9f;
    p.backing = 1;
    p.backing_color = {0.1f, 0.1f, 0.1f};
    const auto [filtered, pointSampled] = farFieldErrors(p, "far field");
    // Measured on llvmpipe: filtered mean 0.027, p99 0.094; point-sampled mean 0.53, p99 0.98.
    // The filter averages 8 positions across each yarn and ignores where in the pixel the
    // elements fall, and the reference keeps some sampling noise of its own: about 2x room.
    EXPECT_LT(filtered.mean, 0.06);
    EXPECT_LT(filtered.p99, 0.2);
    EXPECT_LT(filtered.mean, 0.5 * pointSampled.mean);
}

// Issue 21: at uv 1e6 a float's values lie 1/16 apart (0.75 elements at repeat 12), and 1e10 + 1
// is 1e10 at every corner. The preview and core both shade such uvs by the far field (the uv's
// spacing, |uv| 2^-23 x repeat, is the footprint) instead of point samples of yarn edges. Per
// pixel they differ: the preview's tangent frame comes from screen derivatives of the rounded uv,
// which jump between pixels (measured: mean relative error 2.3), so the test compares the cloth's
// total, measured 1.7 % apart on llvmpipe; 10 % leaves room for other GPUs and is far from black.
TEST(WeaveFilter, HugeUvsShowTheFarFieldInThePreviewAsInCore) {
    WovenParams p;
    p.pattern = {1, 2, 1};
    p.repeat = glm::vec2(12.0f);
    p.yarn_width = 0.9f;
    p.backing = 1;
    for (float offset : {1e6f, 1e10f}) {
        SceneDescription scene = flatClothScene(p);
        for (glm::vec2& uv : scene.meshes[0].uvs) uv += glm::vec2(offset);
        std::vector<uint8_t> onCloth;
        const Image cpu = coreDirectLighting(scene, kWidth, kHeight, 1, &onCloth);
        const Image gpu = previewRadiance(scene, kWidth, kHeight, true, false);
        double gpuSum = 0.0, cpuSum = 0.0;
        for (size_t i = 0; i < onCloth.size(); ++i)
            if (onCloth[i]) {
                gpuSum += gpu.pixels[i].r + gpu.pixels[i].g + gpu.pixels[i].b;
                cpuSum += cpu.pixels[i].r + cpu.pixels[i].g + cpu.pixels[i].b;
            }
        std::cout << "uv offset " << offset << ": preview / core over the cloth " << gpuSum / cpuSum << "\n";
        ASSERT_GT(cpuSum, 0.0);
        EXPECT_NEAR(gpuSum / cpuSum, 1.0, 0.1) << offset;
    }
}

// The same for a draft: per-thread colours enter the far field as the mean colour of the threads
// each pixel covers, the stripes' widths and spacing as the yarn coverage (weaveCoverage()).
TEST(WeaveFilter, DistantDraftApproachesCoresPixelAverage) {
    std::vector<std::string> warnings;
    const WovenParams p = materialFromJson({{"wif", std::string(WOVEN_ASSETS_DIR) + "/drafts/twill_stripes.wif"},
                                            {"repeat", {400, 400}}, {"cy", 0.7}, {"ex", 200}, {"ey", 4},
                                            {"backing", 1}, {"backing_color", 0.1}},
                                           WovenParams{}, "", warnings).params;
    const auto [filtered, pointSampled] = farFieldErrors(p, "far field (draft)");
    // Measured on llvmpipe: filtered mean 0.062, p99 0.26; point-sampled mean 0.81, p99 2.0.
    // More than the plain cloth's: the navy warp is 3x darker than the slate weft and the 2/2
    // twill's lines repeat every 4 threads, about a pixel here, so each pixel's box catches its
    // own share of dark lines, which an average over the repeat cannot follow (as the filter
    // above, it ignores where the elements fall in the pixel). The stripes themselves are kept:
    // a mean colour over the whole repeat instead gives a mean error of 0.44. 1.5x room.
    EXPECT_LT(filtered.mean, 0.09);
    EXPECT_LT(filtered.p99, 0.4);
    EXPECT_LT(filtered.mean, 0.25 * pointSampled.mean);
}

}  // namespace
}  // namespace woven::test
