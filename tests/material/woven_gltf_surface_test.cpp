// A glTF material made woven keeps what the user did not override: its base colour factor as the
// yarn colours, its base colour texture and vertex colour as a print, its alpha cut-out and its
// normal map; "keep_base_color": false and explicit colours override it; a material woven in its
// file keeps its woven colours and ignores its glTF fallback fields. Each from a small glTF file.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <array>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "scene_materials.h"
#include "temp_dir.h"
#include "woven_assignment.h"
#include "woven_material.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using json = nlohmann::json;

// Points at the middle of weave elements (on the top yarn, where the bump leaves the normal as
// it is) of a plain weave with 4 elements per UV unit: the left and right halves of the texture.
constexpr glm::vec2 kLeft{0.125f, 0.125f}, kRight{0.625f, 0.125f};
const glm::vec3 kWo = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
const glm::vec3 kWi = glm::normalize(glm::vec3(-0.4f, 0.1f, 1.0f));
const json kWeave = {{"pattern", {1, 1, 1}}, {"repeat", {4, 4}}};

// The unit square in z = 0 (normal +z, uv = xy) with material "Cloth", and a 4 x 1 RGBA image
// (texture 0) the test fills: texels 0-1 the left half, 2-3 the right.
struct ClothFile {
    TempDir dir;
    SceneDescription scene;

    ClothFile(const json& material, const std::array<glm::u8vec4, 2>& halves = {glm::u8vec4(255), glm::u8vec4(255)},
              const std::vector<glm::vec4>& vertexColors = {}) {
        const glm::u8vec4 texels[4] = {halves[0], halves[0], halves[1], halves[1]};
        stbi_write_png(dir.file("t.png").c_str(), 4, 1, 4, texels, 16);
        GltfBuilder b;
        b.json()["images"] = {{{"uri", "t.png"}}};
        b.json()["textures"] = {{{"source", 0}}};
        json m = material;
        m["name"] = "Cloth";
        json attributes = {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})},
                           {"NORMAL", b.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                           {"TEXCOORD_0", b.addVec2({{0, 0}, {1, 0}, {1, 1}, {0, 1}})}};
        if (!vertexColors.empty()) attributes["COLOR_0"] = b.addVec4(vertexColors);
        const json primitive = {{"attributes", attributes}, {"indices", b.addIndices({0, 1, 2, 0, 2, 3})},
                                {"material", b.addMaterial(m)}};
        b.setScene({b.addNode({{"mesh", b.addMesh(primitive)}})});
        b.writeGltf(dir.file("cloth.gltf"));
        scene = loadScene(dir.file("cloth.gltf"));
    }

    ClothFile& woven(const json& layer = json::object(), const std::string& where = "materials.Cloth") {
        json params = kWeave;
        params.update(layer);
        assignWoven(scene, {{"Cloth", params, where, ""}});
        return *this;
    }
    const Material& material() const { return scene.materials.at(size_t(scene.meshes.at(0).material)); }
    const WovenParams& params() const { return *material().woven; }

    // The hit at `uv` on the front face, with the file's normal and tangents; the footprint
    // `duvdx` along x (zero: a point).
    SurfaceHit hit(glm::vec2 uv, glm::vec2 duvdx = glm::vec2(0.0f)) const {
        SurfaceHit h;
        h.p = glm::vec3(uv, 0.0f);
        h.ng = h.ns = glm::vec3(0, 0, 1);
        h.dpdu = glm::vec3(1, 0, 0);
        h.dpdv = glm::vec3(0, 1, 0);
        h.tex = interpolateTexCoords(scene.meshes.at(0), 0, 0.0f, 0.0f);  // vertex colours
        h.tex.uv[0] = uv;
        h.tex.hasUv = true;
        h.material = scene.meshes.at(0).material;
        h.duvdx = duvdx;
        return h;
    }
    // The BSDF seen from kWo towards kWi, and its shading normal (a filtered BSDF points into its
    // material, so both are read while the materials live).
    glm::vec3 f(glm::vec2 uv, glm::vec2 duvdx = glm::vec2(0.0f)) const {
        const SceneMaterials materials(scene);
        return materials.bsdf(hit(uv, duvdx), kWo)->eval(kWo, kWi);
    }
    glm::vec3 shadingNormal(glm::vec2 uv) const { return SceneMaterials(scene).bsdf(hit(uv), kWo)->shadingNormal(); }
};

json baseColor(glm::vec3 factor, bool textured = false) {
    json pbr = {{"baseColorFactor", {factor.r, factor.g, factor.b, 1.0}}};
    if (textured) pbr["baseColorTexture"] = {{"index", 0}};
    return {{"pbrMetallicRoughness", pbr}};
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float eps) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

TEST(WovenGltfSurface, BaseColourFactorBecomesBothYarnColours) {
    const glm::vec3 orange(1.0f, 0.4f, 0.1f);
    ClothFile cloth(baseColor(orange));
    cloth.woven();
    EXPECT_EQ(cloth.params().weft_color, orange);
    EXPECT_EQ(cloth.params().warp_color, orange);
    // f = R_d x (diffuse shape) + specular, the specular colourless: against black and white
    // cloth, the diffuse part is the factor, channel by channel, on both yarns.
    ClothFile white(baseColor(glm::vec3(1.0f))), black(baseColor(glm::vec3(0.0f)));
    white.woven();
    black.woven();
    for (const glm::vec2 uv : {kLeft, kLeft + glm::vec2(0.25f, 0.0f)}) {  // weft, then warp on top
        const glm::vec3 diffuse = cloth.f(uv) - black.f(uv), unit = white.f(uv) - black.f(uv);
        ASSERT_GT(unit.g, 1e-3f);
        expectNear(diffuse / unit, orange, 1e-4f);
    }
}

TEST(WovenGltfSurface, BaseColourTextureAndVertexColourPrintOnTheYarns) {
    // White left, green right (sRGB 0 and 1 decode to themselves), under a grey factor.
    ClothFile cloth(baseColor(glm::vec3(0.8f), true), {glm::u8vec4(255), glm::u8vec4(0, 255, 0, 255)});
    cloth.woven();
    EXPECT_EQ(cloth.params().weft_color, glm::vec3(0.8f));
    ClothFile black(baseColor(glm::vec3(0.0f), true), {glm::u8vec4(255), glm::u8vec4(0, 255, 0, 255)});
    black.woven();
    // Point-sampled, and filtered over a footprint of several elements.
    for (const glm::vec2 footprint : {glm::vec2(0.0f), glm::vec2(0.3f, 0.0f)}) {
        const glm::vec3 left = cloth.f(kLeft, footprint) - black.f(kLeft, footprint);
        const glm::vec3 right = cloth.f(kRight, footprint) - black.f(kRight, footprint);
        ASSERT_GT(left.g, 1e-3f);
        expectNear(left, glm::vec3(left.g), 1e-6f);              // grey yarn
        expectNear(right, glm::vec3(0.0f, left.g, 0.0f), 1e-6f);  // printed green
    }
    // COLOR_0 multiplies the print as glTF multiplies it into the base colour.
    ClothFile tinted(baseColor(glm::vec3(0.8f)), {glm::u8vec4(255), glm::u8vec4(255)},
                     std::vector<glm::vec4>(4, glm::vec4(0.5f, 1.0f, 1.0f, 1.0f)));
    tinted.woven();
    ClothFile plain(baseColor(glm::vec3(0.8f)));
    plain.woven();
    ClothFile none(baseColor(glm::vec3(0.0f)));
    none.woven();
    const glm::vec3 ratio = (tinted.f(kLeft) - none.f(kLeft)) / (plain.f(kLeft) - none.f(kLeft));
    expectNear(ratio, glm::vec3(0.5f, 1.0f, 1.0f), 1e-4f);
}

TEST(WovenGltfSurface, KeepBaseColorFalseGivesWovensOwnColoursAndNoPrint) {
    const std::array<glm::u8vec4, 2> halves = {glm::u8vec4(255), glm::u8vec4(0, 255, 0, 255)};
    ClothFile cloth(baseColor(glm::vec3(1.0f, 0.4f, 0.1f), true), halves);
    cloth.woven({{"keep_base_color", false}});
    const WovenParams defaults;
    EXPECT_EQ(cloth.params().weft_color, defaults.weft_color);
    EXPECT_EQ(cloth.params().warp_color, defaults.warp_color);
    EXPECT_EQ(cloth.f(kLeft), cloth.f(kRight));  // no print

    // A later layer (a scene file's, then --woven's) turns the factor's colours off again.
    ClothFile later(baseColor(glm::vec3(1.0f, 0.4f, 0.1f), true), halves);
    later.woven().woven({{"keep_base_color", false}}, "--woven Cloth");
    EXPECT_EQ(later.params().weft_color, defaults.weft_color);
    EXPECT_EQ(later.f(kLeft), later.f(kRight));

    ClothFile wrong(baseColor(glm::vec3(1.0f)));
    try {
        wrong.woven({{"keep_base_color", 0}});
        ADD_FAILURE() << "a number was taken for keep_base_color";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("materials.Cloth: 'keep_base_color' must be true or false"), std::string::npos)
            << e.what();
    }
}

TEST(WovenGltfSurface, ExplicitColoursOverrideTheFactor) {
    ClothFile cloth(baseColor(glm::vec3(1.0f, 0.4f, 0.1f)));
    cloth.woven({{"weft_color", {0.1, 0.2, 0.3}}});
    EXPECT_EQ(cloth.params().weft_color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(cloth.params().warp_color, glm::vec3(0.1f, 0.2f, 0.3f));  // follows weft_color, as always
    ClothFile stripes(baseColor(glm::vec3(1.0f, 0.4f, 0.1f)));
    stripes.woven({{"warp_colors", {{0.2, 0.2, 0.2}}}});
    EXPECT_EQ(stripes.params().weft_color, WovenParams().weft_color);
}

TEST(WovenGltfSurface, AlphaMaskCutsOutTheWovenCloth) {
    json m = baseColor(glm::vec3(1.0f), true);
    m["alphaMode"] = "MASK";
    ClothFile cloth(m, {glm::u8vec4(255), glm::u8vec4(255, 255, 255, 0)});
    cloth.woven();
    const SceneMaterials materials(cloth.scene);
    const SurfaceMaterial& woven = materials[cloth.scene.meshes[0].material];
    ASSERT_TRUE(woven.mayPassThrough(cloth.scene.meshes[0]));
    EXPECT_FALSE(woven.passesThrough(cloth.hit(kLeft).tex, 0.0f));
    EXPECT_TRUE(woven.passesThrough(cloth.hit(kRight).tex, 0.0f));
    // And where the weave has a gap, whatever alpha says.
    ClothFile open(m, {glm::u8vec4(255), glm::u8vec4(255)});
    open.woven({{"yarn_width", 0.5}, {"warp_width", 0.5}});
    const SceneMaterials openMaterials(open.scene);
    const SurfaceMaterial& gappy = openMaterials[open.scene.meshes[0].material];
    EXPECT_FALSE(gappy.passesThrough(open.hit(kLeft).tex, 0.0f));
    EXPECT_TRUE(gappy.passesThrough(open.hit(glm::vec2(0.0f)).tex, 0.0f));  // an element's corner
}

TEST(WovenGltfSurface, NormalMapTiltsTheWovenShadingNormal) {
    // (200, 128, 220): tilted towards +x in the tangent frame (+u = +x here).
    const glm::u8vec4 texel(200, 128, 220, 255);
    json m = baseColor(glm::vec3(0.5f));
    m["normalTexture"] = {{"index", 0}};
    ClothFile bumped(m, {texel, texel});
    bumped.woven();
    ClothFile flat(baseColor(glm::vec3(0.5f)));
    flat.woven();
    // At the middle of a yarn the weave's bump is flat: the shading normal is the map's.
    const glm::vec3 expected = glm::normalize(glm::vec3(texel) / 255.0f * 2.0f - 1.0f);
    expectNear(bumped.shadingNormal(kLeft), expected, 1e-5f);
    expectNear(flat.shadingNormal(kLeft), glm::vec3(0, 0, 1), 1e-6f);
    const glm::vec3 a = bumped.f(kLeft), b = flat.f(kLeft);
    EXPECT_GT(glm::length(a - b), 0.01f * glm::length(b));
}

TEST(WovenGltfSurface, MaterialWovenInItsFileKeepsItsColoursAndIgnoresItsFallback) {
    // A WOVEN_fabric material whose PBR fields are other viewers' fallback (as `woven export
    // --keep-woven` writes them): a baked texture, a normal map, a cut-out.
    json m = baseColor(glm::vec3(1.0f, 0.4f, 0.1f), true);
    m["normalTexture"] = {{"index", 0}};
    m["alphaMode"] = "MASK";
    m["extensions"] = {{"WOVEN_fabric", {{"weft_color", {0.2, 0.3, 0.4}}}}};
    ClothFile cloth(m, {glm::u8vec4(255), glm::u8vec4(0, 255, 0, 0)});
    cloth.woven({{"ex", 5}});
    EXPECT_FALSE(cloth.material().keptSurface);
    EXPECT_EQ(cloth.params().weft_color, glm::vec3(0.2f, 0.3f, 0.4f));
    // As the bare model shades it.
    ShadingInput in;
    in.uv = glm::dvec2(kRight);
    const WovenMaterial model(cloth.params());
    EXPECT_EQ(cloth.f(kRight), toBsdf(model.shade(in)->bsdf).eval(kWo, kWi));
    const SceneMaterials materials(cloth.scene);
    EXPECT_FALSE(materials[cloth.scene.meshes[0].material].mayPassThrough(cloth.scene.meshes[0]));
}

}  // namespace
}  // namespace woven
