// glTF materials as the loader reads them: every core input, the KHR material extensions,
// texture references (texCoord, KHR_texture_transform, samplers), vertex colours, a second
// set of texture coordinates, skins and morph targets, each in a small file the test writes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <webp/encode.h>

#include <cmath>
#include <fstream>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float eps = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// A file with one image (a 2 x 1 PNG) used by texture 0, and whatever the test adds.
struct TexturedFile {
    TempDir dir;
    GltfBuilder b;
    TexturedFile() {
        const unsigned char pixels[8] = {255, 0, 0, 255, 0, 128, 255, 64};
        stbi_write_png(dir.file("t.png").c_str(), 2, 1, 4, pixels, 8);
        b.json()["images"] = {{{"uri", "t.png"}}};
        b.json()["textures"] = {{{"source", 0}}};
    }
    SceneDescription load(json material, json attributes = json::object()) {
        const int m = b.addMaterial(material);
        json primitive = {{"attributes", {{"POSITION", b.addPositions(kTriangle)}}}, {"material", m}};
        primitive["attributes"].update(attributes);
        b.setScene({b.addNode({{"mesh", b.addMesh(primitive)}})});
        b.writeGltf(dir.file("m.gltf"));
        return loadScene(dir.file("m.gltf"));
    }
    std::string error(json material) {
        try {
            load(std::move(material));
        } catch (const SceneError& e) {
            return e.what();
        }
        return "(no error)";
    }
};

TEST(GltfMaterialInputs, CoreTexturesAlphaAndSidesAreRead) {
    TexturedFile f;
    const SceneDescription s = f.load({{"name", "M"},
                                       {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.4, 0.3, 0.7}},
                                                                 {"metallicRoughnessTexture", {{"index", 0}}}}},
                                       {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                                       {"occlusionTexture", {{"index", 0}, {"strength", 0.25}}},
                                       {"emissiveTexture", {{"index", 0}}},
                                       {"emissiveFactor", {1, 1, 1}},
                                       {"alphaMode", "MASK"},
                                       {"alphaCutoff", 0.3},
                                       {"doubleSided", true}});
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.4f, 0.3f, 0.7f));
    EXPECT_EQ(m.metallic, 1.0f);  // glTF's defaults where the file says nothing
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(m.metallicRoughnessTexture.image, 0);
    EXPECT_FALSE(m.metallicRoughnessTexture.srgb);  // data
    EXPECT_EQ(m.normalTexture.scale, 0.5f);
    EXPECT_EQ(m.occlusionTexture.scale, 0.25f);
    EXPECT_TRUE(m.emissiveTexture.srgb);  // colour
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(s.textures.size(), 1u);  // one image decoded once for four uses
    EXPECT_EQ(s.textures[0].bytes.at(1), glm::u8vec4(0, 128, 255, 64));  // alpha kept
}

TEST(GltfMaterialInputs, ExtensionsAreRead) {
    TexturedFile f;
    const SceneDescription s = f.load(
        {{"name", "M"},
         {"extensions",
          {{"KHR_materials_ior", {{"ior", 1.8}}},
           {"KHR_materials_specular", {{"specularFactor", 0.6}, {"specularColorFactor", {1, 0.5, 0.25}},
                                       {"specularColorTexture", {{"index", 0}}}}},
           {"KHR_materials_sheen", {{"sheenColorFactor", {0.2, 0.3, 0.4}}, {"sheenRoughnessFactor", 0.6},
                                    {"sheenRoughnessTexture", {{"index", 0}}}}},
           {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.9}, {"clearcoatRoughnessFactor", 0.1},
                                        {"clearcoatNormalTexture", {{"index", 0}, {"scale", 2}}}}},
           {"KHR_materials_transmission", {{"transmissionFactor", 0.8}}},
           {"KHR_materials_anisotropy", {{"anisotropyStrength", 0.7}, {"anisotropyRotation", 1.2},
                                         {"anisotropyTexture", {{"index", 0}}}}},
           {"KHR_materials_volume", {{"thicknessFactor", 0.02}, {"attenuationDistance", 0.5},
                                     {"attenuationColor", {0.9, 0.5, 0.1}}}},
           {"KHR_materials_emissive_strength", {{"emissiveStrength", 3}}}}},
         {"emissiveFactor", {0.5, 0.5, 0.5}}});
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.ior, 1.8f);
    EXPECT_FLOAT_EQ(m.specular, 0.6f);
    expectNear(m.specularColor, {1, 0.5f, 0.25f});
    EXPECT_TRUE(m.specularColorTexture.srgb);
    expectNear(m.sheen.color, {0.2f, 0.3f, 0.4f});
    EXPECT_FLOAT_EQ(m.sheen.roughness, 0.6f);
    EXPECT_FALSE(m.sheen.roughnessTexture.srgb);
    EXPECT_FLOAT_EQ(m.clearcoat.factor, 0.9f);
    EXPECT_FLOAT_EQ(m.clearcoat.roughness, 0.1f);
    EXPECT_EQ(m.clearcoat.normalTexture.scale, 2.0f);
    EXPECT_FLOAT_EQ(m.transmission.factor, 0.8f);
    EXPECT_FLOAT_EQ(m.anisotropy.strength, 0.7f);
    EXPECT_FLOAT_EQ(m.anisotropy.rotation, 1.2f);
    EXPECT_EQ(m.anisotropy.texture.image, 0);
    EXPECT_FALSE(m.anisotropy.texture.srgb);  // directions and strength are data
    EXPECT_FLOAT_EQ(m.transmission.thickness, 0.02f);
    EXPECT_FLOAT_EQ(m.transmission.attenuationDistance, 0.5f);
    expectNear(m.transmission.attenuationColor, {0.9f, 0.5f, 0.1f});
    expectNear(m.emission, {1.5f, 1.5f, 1.5f});
}

TEST(GltfMaterialInputs, IridescenceIsReadWithTheExtensionsDefaults) {
    TexturedFile f;
    const Material m = f.load({{"extensions", {{"KHR_materials_iridescence",
                                                {{"iridescenceFactor", 0.8}, {"iridescenceIor", 1.6},
                                                 {"iridescenceThicknessMinimum", 250}, {"iridescenceThicknessMaximum", 900},
                                                 {"iridescenceTexture", {{"index", 0}}},
                                                 {"iridescenceThicknessTexture", {{"index", 0}}}}}}}})
                           .materials.at(0);
    EXPECT_FLOAT_EQ(m.iridescence.factor, 0.8f);
    EXPECT_FLOAT_EQ(m.iridescence.ior, 1.6f);
    EXPECT_FLOAT_EQ(m.iridescence.thicknessMin, 250.0f);
    EXPECT_FLOAT_EQ(m.iridescence.thicknessMax, 900.0f);
    EXPECT_EQ(m.iridescence.texture.image, 0);
    EXPECT_FALSE(m.iridescence.texture.srgb);  // both textures are linear data
    EXPECT_EQ(m.iridescence.thicknessTexture.image, 0);
    EXPECT_FALSE(m.iridescence.thicknessTexture.srgb);
    const Material d = TexturedFile().load({{"extensions", {{"KHR_materials_iridescence", json::object()}}}}).materials.at(0);
    EXPECT_EQ(d.iridescence.factor, 0.0f);  // the extension's defaults: no effect until a factor is given
    EXPECT_FLOAT_EQ(d.iridescence.ior, 1.3f);
    EXPECT_FLOAT_EQ(d.iridescence.thicknessMin, 100.0f);
    EXPECT_FLOAT_EQ(d.iridescence.thicknessMax, 400.0f);
    EXPECT_THAT(TexturedFile().error({{"name", "I"}, {"extensions", {{"KHR_materials_iridescence", {{"iridescenceIor", 0.5}}}}}}),
                HasSubstr("material 'I'.extensions.KHR_materials_iridescence.iridescenceIor: is 0.5, must be >= 1"));
}

TEST(GltfMaterialInputs, DiffuseTransmissionIsReadWithTheExtensionsDefaults) {
    TexturedFile f;
    const Material m = f.load({{"extensions", {{"KHR_materials_diffuse_transmission",
                                                {{"diffuseTransmissionFactor", 0.25},
                                                 {"diffuseTransmissionTexture", {{"index", 0}}},
                                                 {"diffuseTransmissionColorFactor", {1.0, 0.9, 0.85}},
                                                 {"diffuseTransmissionColorTexture", {{"index", 0}}}}}}}})
                           .materials.at(0);
    EXPECT_FLOAT_EQ(m.diffuseTransmission.factor, 0.25f);
    expectNear(m.diffuseTransmission.color, {1.0f, 0.9f, 0.85f});
    EXPECT_EQ(m.diffuseTransmission.texture.image, 0);
    EXPECT_FALSE(m.diffuseTransmission.texture.srgb);  // the strength in A is linear data
    EXPECT_EQ(m.diffuseTransmission.colorTexture.image, 0);
    EXPECT_TRUE(m.diffuseTransmission.colorTexture.srgb);  // the colour is sRGB-encoded
    const Material d = TexturedFile().load({{"extensions", {{"KHR_materials_diffuse_transmission", json::object()}}}}).materials.at(0);
    EXPECT_EQ(d.diffuseTransmission.factor, 0.0f);  // the extension's defaults: nothing passes until a factor is given
    expectNear(d.diffuseTransmission.color, glm::vec3(1.0f));
    EXPECT_FALSE(d.diffuseTransmission.texture);

    // Bad values name the material, the extension and the key.
    const auto error = [](json extension) {
        return TexturedFile().error({{"name", "L"}, {"extensions", {{"KHR_materials_diffuse_transmission", extension}}}});
    };
    const std::string at = "material 'L'.extensions.KHR_materials_diffuse_transmission.";
    EXPECT_THAT(error({{"diffuseTransmissionFactor", 1.5}}), HasSubstr(at + "diffuseTransmissionFactor: is 1.5, must be in [0"));
    EXPECT_THAT(error({{"diffuseTransmissionFactor", -0.25}}), HasSubstr(at + "diffuseTransmissionFactor: is -0.25, must be in [0"));
    EXPECT_THAT(error({{"diffuseTransmissionFactor", "half"}}), HasSubstr(at + "diffuseTransmissionFactor: must be a finite number"));
    EXPECT_THAT(error({{"diffuseTransmissionColorFactor", {1.0, 0.5}}}),
                HasSubstr(at + "diffuseTransmissionColorFactor: must be an array of 3 numbers"));
    EXPECT_THAT(error({{"diffuseTransmissionColorFactor", {1.0, 1.5, 0.2}}}),
                HasSubstr(at + "diffuseTransmissionColorFactor: must hold numbers in [0, 1]"));
    EXPECT_THAT(error({{"diffuseTransmissionColorFactor", {1.0, nullptr, 0.2}}}),
                HasSubstr(at + "diffuseTransmissionColorFactor: must hold numbers in [0, 1]"));
    EXPECT_THAT(error({{"diffuseTransmissionTexture", {{"index", 4}}}}),
                HasSubstr(at + "diffuseTransmissionTexture: texture 4 does not exist"));
    EXPECT_THAT(error({{"diffuseTransmissionColorTexture", {{"index", -1}}}}),
                HasSubstr(at + "diffuseTransmissionColorTexture.index: must be an integer >= 0"));
}

TEST(GltfMaterialInputs, SpecularGlossinessBecomesMetallicRoughnessAsGltfTransformConvertsIt) {
    {
        TexturedFile f;
        f.b.useExtension("KHR_materials_pbrSpecularGlossiness", true);
        const SceneDescription s =
            f.load({{"pbrMetallicRoughness", {{"metallicFactor", 1}, {"roughnessFactor", 0.1}}},  // other viewers' fallback
                    {"extensions", {{"KHR_materials_pbrSpecularGlossiness",
                                     {{"diffuseFactor", {0.5, 0.25, 1, 0.75}}, {"specularFactor", {0.9, 0.6, 0.3}},
                                      {"glossinessFactor", 0.3}}}}}});
        const Material& m = s.materials.at(0);
        EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
        EXPECT_EQ(m.metallic, 0.0f);
        EXPECT_FLOAT_EQ(m.roughness, 0.7f);  // 1 - glossiness
        EXPECT_EQ(m.ior, 0.0f);              // F0 = specularColor x specular, exactly
        EXPECT_EQ(m.specular, 1.0f);
        expectNear(m.specularColor, {0.9f, 0.6f, 0.3f});
        EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr("KHR_materials_pbrSpecularGlossiness: approximated")));
    }
    {
        // With the texture: specular colour from its RGB (sRGB), roughness 1 - glossiness x A in
        // a texture of its own (G; A is 255 and 64 in t.png: 255 - 0.5 x 255 = 127.5 -> 128,
        // 255 - 0.5 x 64 = 223), the diffuse texture as the base colour's.
        TexturedFile f;
        const SceneDescription s =
            f.load({{"extensions", {{"KHR_materials_pbrSpecularGlossiness",
                                     {{"glossinessFactor", 0.5}, {"diffuseTexture", {{"index", 0}}},
                                      {"specularGlossinessTexture", {{"index", 0}, {"texCoord", 1}}}}}}}});
        const Material& m = s.materials.at(0);
        EXPECT_EQ(m.baseColorTexture.image, 0);
        EXPECT_TRUE(m.baseColorTexture.srgb);
        EXPECT_EQ(m.specularColorTexture.image, 0);
        EXPECT_TRUE(m.specularColorTexture.srgb);
        EXPECT_EQ(m.roughness, 1.0f);
        ASSERT_EQ(m.metallicRoughnessTexture.image, 1);
        EXPECT_FALSE(m.metallicRoughnessTexture.srgb);
        EXPECT_EQ(m.metallicRoughnessTexture.texCoord, 1);  // the specular-glossiness texture's coordinates
        const TextureImage& rough = s.textures.at(1);
        ASSERT_EQ(rough.bytes.size(), 2u);
        EXPECT_EQ(rough.bytes[0], glm::u8vec4(0, 128, 0, 255));
        EXPECT_EQ(rough.bytes[1], glm::u8vec4(0, 223, 0, 255));
    }
}

TEST(GltfMaterialInputs, DispersionIsReadAndNotRendered) {
    TexturedFile f;
    f.b.useExtension("KHR_materials_dispersion");
    const SceneDescription s = f.load({{"extensions", {{"KHR_materials_dispersion", {{"dispersion", 0.4}}}}}});
    EXPECT_THAT(s.warnings, ::testing::Contains("KHR_materials_dispersion: rendered without dispersion (one IOR for every wavelength)"));
    EXPECT_THAT(TexturedFile().error({{"name", "D"}, {"extensions", {{"KHR_materials_dispersion", {{"dispersion", -1}}}}}}),
                HasSubstr("material 'D'.extensions.KHR_materials_dispersion.dispersion: is -1, must be >= 0"));
}

TEST(GltfMaterialInputs, UnlitAndDefaults) {
    TexturedFile f;
    const SceneDescription s = f.load({{"extensions", {{"KHR_materials_unlit", json::object()}}}});
    const Material& m = s.materials.at(0);
    EXPECT_TRUE(m.unlit);
    EXPECT_EQ(m.name, "material0");
    EXPECT_FLOAT_EQ(m.ior, 1.5f);
    EXPECT_FALSE(m.doubleSided);
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
}

TEST(GltfMaterialInputs, TextureTransformTexCoordAndSampler) {
    TexturedFile f;
    f.b.json()["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}, {"minFilter", 9729}}};
    f.b.json()["textures"][0]["sampler"] = 0;
    const SceneDescription s = f.load(
        {{"pbrMetallicRoughness",
          {{"baseColorTexture",
            {{"index", 0}, {"texCoord", 0},
             {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 1.5707963},
                                                        {"scale", {2, 3}}, {"texCoord", 1}}}}}}}}}},
        {{"TEXCOORD_1", f.b.addVec2({{0, 0}, {1, 0}, {0, 1}})}});
    const TextureRef& t = s.materials.at(0).baseColorTexture;
    EXPECT_EQ(t.texCoord, 1);  // the transform's texCoord overrides the textureInfo's
    EXPECT_EQ(t.wrapS, TextureWrap::ClampToEdge);
    EXPECT_EQ(t.wrapT, TextureWrap::MirroredRepeat);
    EXPECT_TRUE(t.nearest);
    EXPECT_FALSE(t.mipmaps);
    // The extension's own example: uv (1, 0) scaled to (2, 0), rotated by 90 degrees to
    // (0, -2) in its convention (rotation matrix rows (cos, sin), (-sin, cos)), plus the offset.
    const glm::vec2 uv = glm::vec2(t.uvTransform * glm::vec3(1, 0, 1));
    EXPECT_NEAR(uv.x, 0.5f, 1e-5f);
    EXPECT_NEAR(uv.y, 0.25f - 2.0f, 1e-5f);
    const glm::vec2 v = glm::vec2(t.uvTransform * glm::vec3(0, 1, 1));  // (0, 3) -> (3, 0) -> + offset
    EXPECT_NEAR(v.x, 3.5f, 1e-5f);
    EXPECT_NEAR(v.y, 0.25f, 1e-5f);
    ASSERT_EQ(s.meshes.at(0).uvs1.size(), 3u);
    EXPECT_EQ(s.meshes[0].uvs1[1], glm::vec2(1, 0));
}

TEST(GltfMaterialInputs, VertexColoursRgbAndNormalizedRgba) {
    TexturedFile f;
    const std::vector<uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0};
    const int colors = f.b.addAccessor(rgba.data(), rgba.size(), test::kUnsignedByte, "VEC4", 3, true);
    const SceneDescription s = f.load(json::object(), {{"COLOR_0", colors}});
    ASSERT_EQ(s.meshes.at(0).colors.size(), 3u);
    EXPECT_NEAR(s.meshes[0].colors[1].g, 1.0f, 1e-6f);
    EXPECT_NEAR(s.meshes[0].colors[1].a, 128.0f / 255.0f, 1e-6f);
    TexturedFile g;
    const SceneDescription rgb = g.load(json::object(), {{"COLOR_0", g.b.addVec3({{0.1f, 0.2f, 0.3f}, {1, 1, 1}, {0, 0, 0}})}});
    EXPECT_EQ(rgb.meshes.at(0).colors[0], glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));  // alpha 1 for RGB
}

TEST(GltfMaterialInputs, OutOfRangeAndMalformedValuesNameTheMaterialAndKey) {
    EXPECT_THAT(TexturedFile().error({{"name", "Red"}, {"pbrMetallicRoughness", {{"roughnessFactor", 1.5}}}}),
                HasSubstr("material 'Red'.pbrMetallicRoughness.roughnessFactor: is 1.5"));
    EXPECT_THAT(TexturedFile().error({{"name", "A"}, {"alphaMode", "SOMETIMES"}}), HasSubstr("material 'A'.alphaMode"));
    EXPECT_THAT(TexturedFile().error({{"name", "T"}, {"normalTexture", {{"index", 7}}}}),
                HasSubstr("material 'T'.normalTexture: texture 7 does not exist"));
    EXPECT_THAT(TexturedFile().error({{"name", "I"}, {"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}),
                HasSubstr("KHR_materials_ior.ior: must be 0 or at least 1"));
    EXPECT_THAT(TexturedFile().error({{"name", "V"}, {"extensions", {{"KHR_materials_volume", {{"attenuationDistance", 0}}}}}}),
                HasSubstr("attenuationDistance: must be a number > 0"));
    // Numbers said as written (%g), not in 302 digits.
    EXPECT_THAT(TexturedFile().error({{"name", "D"}, {"extensions", {{"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 1e300}}}}}}),
                HasSubstr("diffuseTransmissionFactor: is 1e+300, must be in [0, 1]"));
    // An emitter is held to the lights' limit: 1e39 rendered black, 1e20 was clamped silently.
    for (double strength : {1e20, 1e39})
        EXPECT_THAT(TexturedFile().error({{"name", "Sun"},
                                          {"emissiveFactor", {1, 1, 1}},
                                          {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}}),
                    HasSubstr("material 'Sun'.extensions.KHR_materials_emissive_strength.emissiveStrength: is "));
    EXPECT_THAT(TexturedFile().error({{"name", "Sun"},
                                      {"emissiveFactor", {1e5, 1, 1}},
                                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e6}}}}}}),
                HasSubstr("material 'Sun': its emission (emissiveFactor x KHR_materials_emissive_strength) is 1e+11, more than woven's limit"));
    // Float noise just outside a range is clamped, not refused.
    EXPECT_EQ(TexturedFile().load({{"pbrMetallicRoughness", {{"metallicFactor", 1.00000001}}}}).materials[0].metallic, 1.0f);
}

TEST(GltfExtensions, UnsupportedOnesAreNamedRequiredOnesRefused) {
    TexturedFile f;
    f.b.useExtension("EXT_lights_image_based");
    f.b.useExtension("KHR_materials_volume");
    const SceneDescription s = f.load(json::object());
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr("ignores the optional extension EXT_lights_image_based")));
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr("KHR_materials_volume: rendered thin-walled")));
    TexturedFile g;
    g.b.useExtension("EXT_lights_image_based", true);
    EXPECT_THAT(g.error(json::object()), HasSubstr("requires the extension EXT_lights_image_based, which woven does not support"));
    // The extensions woven renders can be required.
    TexturedFile h;
    for (const char* e : {"KHR_texture_transform", "KHR_materials_sheen", "KHR_materials_transmission", "KHR_materials_unlit",
                          "KHR_materials_anisotropy", "KHR_materials_iridescence", "KHR_materials_pbrSpecularGlossiness",
                          "KHR_materials_dispersion", "KHR_materials_diffuse_transmission", "EXT_mesh_gpu_instancing"})
        h.b.useExtension(e, true);
    EXPECT_NO_THROW(h.load(json::object()));
}

TEST(GltfExtensions, ATextureOnlyAnExtensionCanDecodeIsIgnoredWithAWarning) {
    TexturedFile f;
    f.b.json()["textures"].push_back({{"extensions", {{"KHR_texture_basisu", {{"source", 0}}}}}});
    const SceneDescription s = f.load({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}});
    EXPECT_FALSE(s.materials[0].baseColorTexture);
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr("has no PNG, JPEG or WebP image woven can read")));
}

TEST(GltfExtensions, AWebPTextureDecodesAsItsPngTwin) {
    TexturedFile f;
    // The PNG's pixels, written by libwebp's lossless encoder.
    const unsigned char pixels[8] = {255, 0, 0, 255, 0, 128, 255, 64};
    uint8_t* webp = nullptr;
    const size_t size = WebPEncodeLosslessRGBA(pixels, 2, 1, 8, &webp);
    ASSERT_GT(size, 0u);
    std::ofstream(f.dir.file("t.webp"), std::ios::binary).write(reinterpret_cast<const char*>(webp), std::streamsize(size));
    WebPFree(webp);
    f.b.json()["images"].push_back({{"uri", "t.webp"}});
    // Its "source" is the fallback for viewers without WebP, which woven is not.
    f.b.json()["textures"].push_back({{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}});
    f.b.useExtension("EXT_texture_webp", true);
    const SceneDescription s = f.load({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}},
                                       {"emissiveTexture", {{"index", 0}}}});
    const Material& m = s.materials.at(0);
    ASSERT_TRUE(m.baseColorTexture && m.emissiveTexture);
    ASSERT_NE(m.baseColorTexture.image, m.emissiveTexture.image);  // two images, one from each file
    const TextureImage &fromWebp = s.textures.at(size_t(m.baseColorTexture.image)), &fromPng = s.textures.at(size_t(m.emissiveTexture.image));
    EXPECT_EQ(fromWebp.width, 2);
    EXPECT_EQ(fromWebp.bytes, fromPng.bytes);
}

TEST(GltfExtensions, ACorruptWebPTextureIsRefusedNamingIt) {
    TexturedFile f;
    std::ofstream(f.dir.file("bad.webp"), std::ios::binary) << std::string("RIFF\x20\0\0\0WEBPVP8 \x14\0\0\0garbage garbage!!", 36);
    f.b.json()["images"].push_back({{"uri", "bad.webp"}});
    f.b.json()["textures"].push_back({{"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}});
    EXPECT_THAT(f.error({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}}),
                AllOf(HasSubstr("bad.webp"), HasSubstr("cannot decode the WebP image")));
}

// Skins and morph targets: the default pose, with the default weights.
TEST(GltfDeformation, MorphTargetsAtTheirDefaultWeights) {
    TempDir dir;
    GltfBuilder b;
    const int target0 = b.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int target1 = b.addVec3({{1, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)}}},
                                {"targets", {{{"POSITION", target0}}, {{"POSITION", target1}}}}});
    b.json()["meshes"][mesh]["weights"] = {0.5, 0.25};
    const int overridden = b.addNode({{"mesh", mesh}, {"weights", {1.0, 0.0}}, {"translation", {0, 0, 10}}});
    b.setScene({b.addNode({{"mesh", mesh}}), overridden});
    b.writeGltf(dir.file("morph.gltf"));
    const SceneDescription s = loadScene(dir.file("morph.gltf"));
    ASSERT_EQ(s.meshes.size(), 2u);
    expectNear(s.meshes[0].positions[0], {0.25f, 0, 0.5f});  // 0.5 (0,0,1) + 0.25 (1,0,0)
    expectNear(s.meshes[0].positions[2], {0, 1, 0.5f});
    expectNear(s.meshes[1].positions[0], {0, 0, 11});  // the node's weights win
}

TEST(GltfDeformation, SkinPlacesVerticesByTheJointsNotTheMeshNode) {
    TempDir dir;
    GltfBuilder b;
    // Two joints: joint 0 at the origin, joint 1 translated by (0, 5, 0). Vertex 2 follows joint
    // 1 alone, vertex 1 half of each; the bind matrices are identity.
    const std::vector<uint8_t> joints = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    const std::vector<glm::vec4> weights = {{1, 0, 0, 0}, {0.5f, 0.5f, 0, 0}, {1, 0, 0, 0}};
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)},
                                                {"JOINTS_0", b.addAccessor(joints.data(), joints.size(), test::kUnsignedByte, "VEC4", 3)},
                                                {"WEIGHTS_0", b.addVec4(weights)}}}});
    const int joint0 = b.addNode({{"name", "root"}});
    const int joint1 = b.addNode({{"translation", {0, 5, 0}}});
    b.json()["skins"] = {{{"joints", {joint0, joint1}}}};
    // The mesh node's own transform is ignored for a skinned mesh.
    b.setScene({b.addNode({{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}}), joint0, joint1});
    b.writeGltf(dir.file("skin.gltf"));
    const SceneDescription s = loadScene(dir.file("skin.gltf"));
    ASSERT_EQ(s.meshes.size(), 1u);
    expectNear(s.meshes[0].positions[0], {0, 0, 0});
    expectNear(s.meshes[0].positions[1], {1, 2.5f, 0});
    expectNear(s.meshes[0].positions[2], {0, 6, 0});
}

TEST(GltfDeformation, InverseBindMatricesAreMat4Accessors) {
    TempDir dir;
    GltfBuilder b;
    // One joint at (0, 5, 0) whose inverse bind matrix undoes that translation: the mesh stays
    // where its bind pose puts it. A MAT4 accessor of floats, column-major.
    const std::vector<uint8_t> joints(12, 0);
    const std::vector<glm::vec4> weights(3, glm::vec4(1, 0, 0, 0));
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)},
                                                {"JOINTS_0", b.addAccessor(joints.data(), joints.size(), test::kUnsignedByte, "VEC4", 3)},
                                                {"WEIGHTS_0", b.addVec4(weights)}}}});
    const glm::mat4 inverseBind(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -5, 2, 1);  // translate (0, -5, 2)
    const int joint = b.addNode({{"translation", {0, 5, 0}}});
    b.json()["skins"] = {{{"joints", {joint}}, {"inverseBindMatrices", b.addAccessor(&inverseBind[0][0], 64, test::kFloat, "MAT4", 1)}}};
    b.setScene({b.addNode({{"mesh", mesh}, {"skin", 0}}), joint});
    b.writeGltf(dir.file("bind.gltf"));
    const SceneDescription s = loadScene(dir.file("bind.gltf"));
    expectNear(s.meshes.at(0).positions[1], {1, 0, 2});  // (1, 0, 0) - (0, 5, -2) + (0, 5, 0)
}

TEST(GltfLights, PhotometricUnitsBecomeRadiometricByBlendersRule) {
    TempDir dir;
    GltfBuilder b;
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 683}},
                                                              {{"type", "directional"}, {"intensity", 68.3}}};
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)}}}})}}),
                b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}),
                b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}})});
    b.writeGltf(dir.file("units.gltf"));
    const SceneDescription s = loadScene(dir.file("units.gltf"));
    // 683 cd = 1 W/sr, 68.3 lx = 0.1 W/m^2.
    expectNear(s.lights.at(0).intensity, glm::vec3(1.0f));
    expectNear(s.lights.at(1).intensity, glm::vec3(0.1f));
}

}  // namespace
}  // namespace woven
