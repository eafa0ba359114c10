// GltfMaterial's inputs at a point: factors times textures times vertex colour, the
// metallic-roughness channels, the specular/IOR Fresnel, the normal map in the tangent frame
// (handedness included), alpha MASK and BLEND, unlit and emission.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_material.h"
#include "sampling.h"

namespace woven {
namespace {

TextureImage oneTexel(glm::u8vec4 value) {
    TextureImage t;
    t.width = t.height = 1;
    t.bytes = {value};
    return t;
}

TexCoords point(glm::vec4 color = glm::vec4(1.0f)) {
    TexCoords tc;
    tc.uv[0] = {0.5f, 0.5f};
    tc.hasUv = true;
    tc.color = color;
    return tc;
}

TEST(GltfMaterial, BaseColourMetallicRoughnessAndFresnelInputs) {
    // Texture 0: (128, 64, 255, 255) linear data for metallic-roughness, sRGB white-ish for colour.
    const std::vector<TextureImage> textures = {oneTexel({255, 102, 51, 255})};
    Material m;
    m.baseColor = glm::vec4(0.5f, 1.0f, 1.0f, 1.0f);
    m.baseColorTexture.image = 0;  // linear here, so the numbers are bytes / 255
    m.metallic = 0.5f;
    m.roughness = 0.8f;
    m.metallicRoughnessTexture.image = 0;
    m.ior = 2.0f;
    m.specular = 0.5f;
    m.specularColor = glm::vec3(1.0f, 0.5f, 0.5f);
    const GltfMaterial g(m, textures);
    const GltfBxdfInputs in = g.inputs(point(glm::vec4(1.0f, 0.5f, 1.0f, 1.0f)));
    EXPECT_NEAR(in.baseColor.r, 0.5f, 1e-6f);               // 0.5 x 1 x 1
    EXPECT_NEAR(in.baseColor.g, 102 / 255.0f * 0.5f, 1e-6f);  // 1 x 0.4 x 0.5 (vertex colour)
    EXPECT_NEAR(in.metallic, 0.5f * 51 / 255.0f, 1e-6f);    // B channel
    EXPECT_NEAR(in.roughness, 0.8f * 102 / 255.0f, 1e-6f);  // G channel
    // ((2 - 1) / (2 + 1))^2 = 1/9, times the specular colour, times the specular factor.
    EXPECT_NEAR(in.specularF0.r, 0.5f / 9.0f, 1e-6f);
    EXPECT_NEAR(in.specularF0.g, 0.25f / 9.0f, 1e-6f);
    EXPECT_NEAR(in.specularF90, 0.5f, 1e-6f);
}

// A hit on the z = 0 plane with the file's normal +z, tangent +x and bitangent sign `w`.
SurfaceHit planeHit(float w) {
    SurfaceHit hit;
    hit.ng = hit.ns = glm::vec3(0, 0, 1);
    hit.dpdu = glm::vec3(1, 0, 0);
    hit.dpdv = w * glm::vec3(0, 1, 0);
    hit.tex = point();
    return hit;
}

TEST(GltfMaterial, NormalMapTiltsTheNormalInTheTangentFrame) {
    // Tangent-space (0.6, 0, 0.8) and (0, 0.6, 0.8), 8-bit encoded: (v + 1) / 2 * 255.
    const auto encode = [](glm::vec3 v) { return glm::u8vec4(glm::round((v + 1.0f) * 0.5f * 255.0f), 255); };
    Material m;
    m.normalTexture.image = 0;
    // Materials keep pointers to their images: the vectors outlive them.
    const std::vector<TextureImage> u = {oneTexel(encode({0.6f, 0.0f, 0.8f}))}, v = {oneTexel(encode({0.0f, 0.6f, 0.8f}))};
    const GltfMaterial alongU(m, u);
    const glm::vec3 n = alongU.shadingNormal(planeHit(1.0f));
    EXPECT_NEAR(n.x, 0.6f, 5e-3f);
    EXPECT_NEAR(n.y, 0.0f, 5e-3f);
    EXPECT_NEAR(n.z, 0.8f, 5e-3f);

    const GltfMaterial alongV(m, v);
    EXPECT_NEAR(alongV.shadingNormal(planeHit(1.0f)).y, 0.6f, 5e-3f);
    // Mirrored UVs: the bitangent, hence the tilt, turns over.
    EXPECT_NEAR(alongV.shadingNormal(planeHit(-1.0f)).y, -0.6f, 5e-3f);

    // The scale multiplies x and y before normalising: (0.3, 0, 0.8) / |.|.
    m.normalTexture.scale = 0.5f;
    const glm::vec3 half = GltfMaterial(m, u).shadingNormal(planeHit(1.0f));
    EXPECT_NEAR(half.x, 0.3f / std::sqrt(0.73f), 5e-3f);

    // A file normal pointing against ng: the map is applied in the file's frame, then turned.
    SurfaceHit flipped = planeHit(1.0f);
    flipped.nsFlipped = true;
    flipped.ng = glm::vec3(0, 0, -1);
    flipped.ns = glm::vec3(0, 0, -1);
    const glm::vec3 f = alongU.shadingNormal(flipped);
    EXPECT_NEAR(f.x, -0.6f, 5e-3f);
    EXPECT_NEAR(f.z, -0.8f, 5e-3f);
}

// A normal map tilted so far that the mirror direction of a grazing view falls below the
// surface: the BSDF's normal is tilted back until the mirror direction stays just above it, so
// the highlight does not turn black (as in Cycles).
TEST(GltfMaterial, AnisotropyDirectionFromTextureAndRotationInTheTangentFrame) {
    // Texture direction (0, 1) (along the bitangent), strength 0.5 in blue; rotated by 90 degrees
    // it points along -tangent. Without a texture the rotation turns the tangent.
    const std::vector<TextureImage> textures = {oneTexel({128, 255, 128, 255})};
    Material m;
    m.anisotropy.strength = 0.8f;
    m.anisotropy.texture.image = 0;
    const GltfMaterial textured(m, textures);
    EXPECT_NEAR(textured.inputs(point()).anisotropy, 0.8f * 128 / 255.0f, 1e-6f);
    glm::vec3 d = textured.anisotropyDirection(planeHit(1.0f));
    EXPECT_NEAR(d.x, 0.0f, 1e-2f);
    EXPECT_NEAR(d.y, 1.0f, 1e-4f);
    // Mirrored UVs turn the bitangent over, and the direction with it.
    EXPECT_NEAR(textured.anisotropyDirection(planeHit(-1.0f)).y, -1.0f, 1e-4f);
    m.anisotropy.rotation = 0.5f * 3.14159265f;
    d = GltfMaterial(m, textures).anisotropyDirection(planeHit(1.0f));
    EXPECT_NEAR(d.x, -1.0f, 1e-4f);
    EXPECT_NEAR(d.y, 0.0f, 1e-2f);

    Material plain;
    plain.anisotropy.strength = 0.5f;
    plain.anisotropy.rotation = 0.3f;
    const GltfMaterial rotated(plain, {});
    EXPECT_FLOAT_EQ(rotated.inputs(point()).anisotropy, 0.5f);
    d = rotated.anisotropyDirection(planeHit(1.0f));
    EXPECT_NEAR(d.x, std::cos(0.3f), 1e-6f);
    EXPECT_NEAR(d.y, std::sin(0.3f), 1e-6f);
}

TEST(GltfMaterial, AnisotropicHighlightStretchesAlongItsDirection) {
    // A smooth metal made rough along x: seen from above with light from the mirror direction
    // tilted by 0.3 rad along x the lobe is still bright, tilted as much along y it is dark.
    Material m;
    m.metallic = 1.0f;
    m.roughness = 0.1f;
    m.anisotropy.strength = 0.8f;
    const GltfMaterial g(m, {});
    const SurfaceHit hit = planeHit(1.0f);
    const glm::vec3 wo(0.0f, 0.0f, 1.0f);
    const auto bsdf = g.bsdf(hit, wo);
    ASSERT_TRUE(bsdf);
    const float alongX = bsdf->eval(wo, glm::normalize(glm::vec3(std::sin(0.3f), 0.0f, std::cos(0.3f)))).g;
    const float alongY = bsdf->eval(wo, glm::normalize(glm::vec3(0.0f, std::sin(0.3f), std::cos(0.3f)))).g;
    EXPECT_GT(alongX, 100.0f * alongY);
}

TEST(GltfMaterial, AnUntexturedSurfaceShadesAsTheSameSurfaceTexturedInWhite) {
    // An untextured material builds its lobes once; a white metallic-roughness texture (x 1 on
    // every input) makes the same material build them at each hit. Both must agree to the bit,
    // with and without a vertex colour, for lobes of every kind and an anisotropic frame.
    const std::vector<TextureImage> white = {oneTexel({255, 255, 255, 255})};
    Material m;
    m.baseColor = glm::vec4(0.6f, 0.3f, 0.2f, 1.0f);
    m.metallic = 0.3f;
    m.roughness = 0.4f;
    m.anisotropy.strength = 0.5f;
    m.sheen.color = glm::vec3(0.2f, 0.4f, 0.1f);
    m.sheen.roughness = 0.5f;
    m.transmission.factor = 0.3f;
    m.iridescence.factor = 0.5f;
    Material textured = m;
    textured.metallicRoughnessTexture.image = 0;
    const GltfMaterial once(m, white), perHit(textured, white);
    for (const glm::vec4 colour : {glm::vec4(1.0f), glm::vec4(0.5f, 0.8f, 1.0f, 1.0f)}) {
        SurfaceHit hit = planeHit(1.0f);
        hit.tex = point(colour);
        const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
        const auto a = once.bsdf(hit, wo), b = perHit.bsdf(hit, wo);
        ASSERT_TRUE(a && b);
        Rng rng(7);
        for (int i = 0; i < 64; ++i) {
            const glm::vec3 wi = sampleUniformSphere(rng.uniform2());
            ASSERT_EQ(a->eval(wo, wi), b->eval(wo, wi)) << i;
            ASSERT_EQ(a->pdf(wo, wi), b->pdf(wo, wi)) << i;
            const glm::vec2 u = rng.uniform2();
            const float uc = rng.uniform();
            const auto sa = a->sample(wo, u, uc), sb = b->sample(wo, u, uc);
            ASSERT_EQ(bool(sa), bool(sb)) << i;
            if (sa) {
                ASSERT_EQ(sa->wi, sb->wi) << i;
            }
        }
    }
}

TEST(GltfMaterial, NormalMapNeverSendsTheMirrorDirectionBelowTheSurface) {
    const auto encode = [](glm::vec3 v) { return glm::u8vec4(glm::round((v + 1.0f) * 0.5f * 255.0f), 255); };
    Material m;
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    m.normalTexture.image = 0;
    const std::vector<TextureImage> steep = {oneTexel(encode(glm::normalize(glm::vec3(0.8f, 0.0f, 0.6f))))};
    const GltfMaterial g(m, steep);
    // Seen from -x, against the tilt: the mirror about the map's normal would point into the plane.
    const glm::vec3 wo = glm::normalize(glm::vec3(-0.2f, 0.0f, 1.0f));
    const auto bsdf = g.bsdf(planeHit(1.0f), wo);
    ASSERT_TRUE(bsdf);
    const glm::vec3 n = bsdf->shadingNormal();
    const glm::vec3 mirror = 2.0f * glm::dot(wo, n) * n - wo;
    EXPECT_GE(mirror.z, 0.009f);
    EXPECT_LT(mirror.z, 0.05f);  // tilted back only as far as needed
    // A gentle view keeps the map's normal as it is.
    const glm::vec3 above = glm::normalize(glm::vec3(0.5f, 0.0f, 1.0f));
    EXPECT_NEAR(glm::dot(g.bsdf(planeHit(1.0f), above)->shadingNormal(), g.shadingNormal(planeHit(1.0f))), 1.0f, 1e-5f);
}

TEST(GltfMaterial, AlphaMaskCutsOutAndBlendPassesInProportion) {
    Material m;
    m.baseColor.a = 0.3f;
    m.alphaMode = AlphaMode::Opaque;
    Mesh mesh;
    EXPECT_FALSE(GltfMaterial(m, {}).mayPassThrough(mesh));  // opaque ignores alpha
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.5f;
    const GltfMaterial mask(m, {});
    EXPECT_TRUE(mask.mayPassThrough(mesh));
    EXPECT_TRUE(mask.passesThrough(point(), 0.99f));  // 0.3 < 0.5: cut out, whatever u
    m.alphaCutoff = 0.2f;
    EXPECT_FALSE(GltfMaterial(m, {}).passesThrough(point(), 0.01f));
    // Vertex colour alpha multiplies: 0.3 x 0.5 = 0.15 < 0.2.
    EXPECT_TRUE(GltfMaterial(m, {}).passesThrough(point(glm::vec4(1, 1, 1, 0.5f)), 0.0f));

    m.alphaMode = AlphaMode::Blend;
    const GltfMaterial blend(m, {});
    Rng rng(5);
    int passed = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) passed += blend.passesThrough(point(), rng.uniform());
    // Binomial with p = 0.7: 5 standard deviations is 0.007.
    EXPECT_NEAR(passed / double(n), 0.7, 5.0 * std::sqrt(0.7 * 0.3 / n));

    // Fully opaque BLEND with no texture and no vertex colours needs no filter at all.
    m.baseColor.a = 1.0f;
    EXPECT_FALSE(GltfMaterial(m, {}).mayPassThrough(mesh));
    mesh.colors.assign(1, glm::vec4(1.0f));
    EXPECT_TRUE(GltfMaterial(m, {}).mayPassThrough(mesh));
}

TEST(GltfMaterial, UnlitShowsItsColourAndReflectsNothing) {
    Material m;
    m.unlit = true;
    m.baseColor = glm::vec4(0.2f, 0.4f, 0.6f, 1.0f);
    m.emission = glm::vec3(5.0f);  // ignored by unlit materials
    const GltfMaterial g(m, {});
    EXPECT_FALSE(g.bsdf(planeHit(1.0f), glm::vec3(0, 0, 1)));
    EXPECT_EQ(g.unlitRadiance(point()), glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_FALSE(g.emits());
}

TEST(GltfMaterial, EmissionIsFactorTimesTexture) {
    Material m;
    m.emission = glm::vec3(2.0f, 1.0f, 0.5f);
    m.emissiveTexture.image = 0;
    m.emissiveTexture.srgb = true;
    const std::vector<TextureImage> textures = {oneTexel({255, 128, 0, 255})};
    const GltfMaterial g(m, textures);
    EXPECT_TRUE(g.emits());
    const glm::vec3 e = g.emission(point());
    EXPECT_NEAR(e.r, 2.0f, 1e-6f);
    EXPECT_NEAR(e.g, 0.2158605f, 1e-6f);  // sRGB 128
    EXPECT_NEAR(e.b, 0.0f, 1e-6f);
    EXPECT_EQ(GltfMaterial(Material{}, {}).emission(point()), glm::vec3(0.0f));
}

}  // namespace
}  // namespace woven
