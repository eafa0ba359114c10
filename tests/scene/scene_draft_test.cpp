// Drafts named by materials (docs/DRAFTS.md, "Drafts in scenes"): "wif" resolved against the
// scene file's directory or, for --woven, the working directory; "scale": "draft" through the
// mesh's measured UV-to-world scale; warnings and errors naming the scene file, the key and the
// draft file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "gltf_builder.h"
#include "woven_assignment.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "uv_scale.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

// Plain weave on 2 shafts by lift plan, 4 x 4 threads: ends 0.05 cm apart (20 per cm), picks
// 0.1 cm (10 per cm), thickness 0.04 cm (warp width 0.8, weft 0.4); ends red, red, blue, blue.
const char* kDraft = R"([WIF]
Version=1.1
[WEAVING]
Shafts=2
Treadles=0
[WARP]
Threads=4
Units=Centimeters
Spacing=0.05
Thickness=0.04
[WEFT]
Threads=4
Units=Centimeters
Spacing=0.1
Thickness=0.04
[COLOR PALETTE]
Entries=2
Range=0,255
[COLOR TABLE]
1=255,0,0
2=0,0,255
[WARP COLORS]
1=1
2=1
3=2
4=2
[THREADING]
1=1
2=2
3=1
4=2
[LIFTPLAN]
1=1
2=2
3=1
4=2
)";

// kDraft with `from` replaced by `to`.
std::string draftWith(const std::string& from, const std::string& to) {
    std::string text = kDraft;
    return text.replace(text.find(from), from.size(), to);
}

// "Cloth": a 2 m x 1 m quad with UVs (0, 0) to (1, 1), so one UV unit is 2 m along u and 1 m
// along v. "Bare": a triangle without UVs. In sub/scene.gltf, the draft in sub/drafts/plain.wif.
class SceneDraft : public ::testing::Test {
protected:
    void SetUp() override {
        std::filesystem::create_directories(dir.file("sub/drafts"));
        std::ofstream(dir.file("sub/drafts/plain.wif"), std::ios::binary) << kDraft;
        GltfBuilder b;
        b.addMaterial({{"name", "Cloth"}});
        b.addMaterial({{"name", "Bare"}});
        const int quad = b.addPositions({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
        const int uvs = b.addVec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
        const int triangle = b.addPositions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
        b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", quad}, {"TEXCOORD_0", uvs}}},
                                                   {"indices", b.addIndices({0, 1, 2, 0, 2, 3})},
                                                   {"material", 0}})}}),
                    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", triangle}}}, {"material", 1}})}})});
        b.writeGltf(dir.file("sub/scene.gltf"));
    }

    std::string write(const json& materials) {
        const std::string path = dir.file("sub/scene.json");
        std::ofstream(path) << json{{"gltf", "scene.gltf"}, {"materials", materials}}.dump(2);
        return path;
    }

    std::string error(const json& materials) {
        const std::string path = write(materials);
        try {
            loadScene(path);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "(no error)";
    }

    TempDir dir;
};

TEST_F(SceneDraft, WifIsResolvedAgainstTheSceneFile) {
    const SceneDescription scene = loadScene(write({{"Cloth", {{"wif", "drafts/plain.wif"}, {"cy", 0.25}}}}));
    const WovenParams& p = scene.materials[0].woven.value();
    EXPECT_EQ(p.tile, (std::vector<std::string>{"|-|-", "-|-|", "|-|-", "-|-|"}));
    ASSERT_EQ(p.warp_colors.size(), 4u);
    EXPECT_EQ(p.warp_colors[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(p.warp_colors[3], glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(p.warp_width, 0.8f);
    EXPECT_FLOAT_EQ(p.yarn_width, 0.4f);
    EXPECT_EQ(p.cy, 0.25f);
    EXPECT_EQ(p.repeat, WovenParams{}.repeat);  // no "scale": the material's own repeat
    EXPECT_EQ(scene.materials[0].draft, dir.file("sub/drafts/plain.wif"));  // for the previewer's draft view
    EXPECT_EQ(scene.materials[1].draft, "");
}

// The primitives of material `m`.
std::vector<size_t> meshesWith(const SceneDescription& scene, int m) {
    std::vector<size_t> meshes;
    for (size_t i = 0; i < scene.meshes.size(); ++i)
        if (scene.meshes[i].material == m) meshes.push_back(i);
    return meshes;
}

TEST_F(SceneDraft, ScaleDraftUsesTheMeshsUvToWorldScale) {
    SceneDescription scene = loadScene(write(json::object()));
    const glm::dvec2 length = worldLengthPerUv(scene, meshesWith(scene, 0));
    EXPECT_NEAR(length.x, 2.0, 1e-6);
    EXPECT_NEAR(length.y, 1.0, 1e-6);
    // 20 ends per cm over 200 cm per UV unit; 10 picks per cm over 100 cm.
    scene = loadScene(write({{"Cloth", {{"wif", "drafts/plain.wif"}, {"scale", "draft"}}}}));
    EXPECT_NEAR(scene.materials[0].woven->repeat.x, 4000.0f, 1e-2f);
    EXPECT_NEAR(scene.materials[0].woven->repeat.y, 1000.0f, 1e-2f);
}

TEST_F(SceneDraft, MistakesNameTheSceneFileTheKeyAndTheDraft) {
    const std::string scene = dir.file("sub/scene.json");
    EXPECT_EQ(error({{"Cloth", {{"wif", "drafts/none.wif"}}}}),
              scene + ": materials.Cloth: " + dir.file("sub/drafts/none.wif") + ": no such file");
    EXPECT_EQ(error({{"Bare", {{"wif", "drafts/plain.wif"}, {"scale", "draft"}}}}),
              scene + ": materials.Bare: no triangle with texture coordinates to measure, which "
                      "\"scale\": \"draft\" and thread counts need");
    EXPECT_THAT(error({{"Cloth", {{"wif", "drafts/plain.wif"}, {"cy", 2}}}}), HasSubstr(scene + ": materials.Cloth: 'cy' = 2"));
    EXPECT_THAT(error({{"Cloth", {{"scale", "draft"}}}}), HasSubstr(scene + ": materials.Cloth: 'scale': \"draft\" needs a draft"));
    // A draft whose threads per cm put more than 1e6 threads on one UV unit.
    std::ofstream(dir.file("sub/drafts/fine.wif"), std::ios::binary) << draftWith("Spacing=0.05", "Spacing=1e-7");
    EXPECT_THAT(error({{"Cloth", {{"wif", "drafts/fine.wif"}, {"scale", "draft"}}}}),
                HasSubstr(scene + ": materials.Cloth: 'scale': \"draft\" gives 'repeat'[0]"));
}

TEST_F(SceneDraft, DraftWarningsNameTheSceneFileAndKey) {
    // Thickness beyond spacing on the weft: filled cells, one warning.
    std::ofstream(dir.file("sub/drafts/thick.wif"), std::ios::binary)
        << draftWith("Spacing=0.1\nThickness=0.04", "Spacing=0.1\nThickness=0.2");
    const SceneDescription scene = loadScene(write({{"*", {{"wif", "drafts/thick.wif"}}}}));
    ASSERT_EQ(scene.warnings.size(), 1u);  // once, though "*" selects two materials
    EXPECT_EQ(scene.warnings[0], dir.file("sub/scene.json") + ": materials.*: " + dir.file("sub/drafts/thick.wif") +
                                     ": 4 weft threads are thicker than their spacing: their yarns fill their cells (width 1)");
}

TEST_F(SceneDraft, WovenOptionResolvesAgainstTheWorkingDirectory) {
    SceneDescription scene = loadScene(dir.file("sub/scene.gltf"));
    char previous[4096];
    ASSERT_NE(getcwd(previous, sizeof previous), nullptr);
    ASSERT_EQ(chdir(dir.file("sub/drafts").c_str()), 0);
    try {
        assignWoven(scene, {parseWovenOption(scene, R"(Cloth={"wif": "plain.wif", "scale": "draft", "ex": 7})")});
    } catch (...) {
        ASSERT_EQ(chdir(previous), 0);
        throw;
    }
    ASSERT_EQ(chdir(previous), 0);
    const WovenParams& p = scene.materials[0].woven.value();
    EXPECT_EQ(p.ex, 7.0f);
    EXPECT_EQ(p.warp_colors.size(), 4u);
    EXPECT_NEAR(p.repeat.x, 4000.0f, 1e-2f);
    // The same option from elsewhere: the draft is not found, and the message says where it looked.
    EXPECT_THAT([&] {
        try {
            assignWoven(scene, {parseWovenOption(scene, R"(Cloth={"wif": "plain.wif"})")});
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    }(), HasSubstr("--woven Cloth: plain.wif: no such file"));
}

// The draft scenes of assets/: they load without a warning, their cloth carries its draft, and
// the real-scale houndstooth puts 20 threads per cm (spacing 0.05 cm) on the draped cloth, whose
// UVs span it once, about 1.7 m (its bounds) with the drape's folds.
TEST(DraftAssets, SceneFilesCarryTheirDrafts) {
    for (const char* name : {"houndstooth", "gingham", "twill_stripes", "houndstooth_real_scale"}) {
        SCOPED_TRACE(name);
        const SceneDescription scene = loadScene(std::string(WOVEN_ASSETS_DIR) + "/" + name + ".json");
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
        const Material& cloth = scene.materials[0];
        ASSERT_EQ(cloth.name, "Cloth");
        EXPECT_NE(cloth.draft.find("assets/drafts/"), std::string::npos);
        EXPECT_FALSE(cloth.woven->tile.empty());
    }
    const SceneDescription real = loadScene(std::string(WOVEN_ASSETS_DIR) + "/houndstooth_real_scale.json");
    const glm::dvec2 metres = worldLengthPerUv(real, meshesWith(real, 0));
    EXPECT_GT(metres.x, 1.2);
    EXPECT_LT(metres.x, 2.2);
    EXPECT_NEAR(real.materials[0].woven->repeat.x, 2000.0 * metres.x, 1e-3 * 2000.0 * metres.x);
    EXPECT_NEAR(real.materials[0].woven->repeat.y, 2000.0 * metres.y, 1e-3 * 2000.0 * metres.y);
}

}  // namespace
}  // namespace woven
