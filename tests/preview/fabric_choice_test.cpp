// The panel's Fabrics menu without its window: a fabric chosen there is the material a scene
// file's {"preset": NAME} makes on the same mesh, the panel's measures of it are `woven fabrics`'
// (until its yarns are edited), and its thumbnail is its drawdown in its thread colours.
#include <gtest/gtest.h>

#include <set>

#include "fabric_choice.h"
#include "fabric_menu.h"
#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "woven_assignment.h"
#include "woven_params_json.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using json = nlohmann::json;

// A square of 5 cm whose UVs span it once: 100 x 0.05 = 5 cm per UV unit.
SceneDescription swatch(const TempDir& dir) {
    GltfBuilder b;
    const float s = 0.05f;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, 0, 0}, {s, s, 0}, {0, s, 0}};
    const std::vector<glm::vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    const json primitive = {{"attributes", {{"POSITION", b.addPositions(p)}, {"TEXCOORD_0", b.addVec2(uv)}}},
                            {"material", b.addMaterial({{"name", "Swatch"}})}};
    b.setScene({b.addNode({{"name", "Swatch"}, {"mesh", b.addMesh(primitive, "Swatch")}})});
    b.writeGltf(dir.file("swatch.gltf"));
    return loadScene(dir.file("swatch.gltf"));
}

TEST(FabricChoice, IsTheMaterialASceneFilesPresetMakesOnTheMesh) {
    TempDir dir;
    for (const char* name : {"denim", "poplin", "tartan"}) {
        SCOPED_TRACE(name);
        SceneDescription panel = swatch(dir), file = swatch(dir);
        std::vector<std::string> warnings;
        const ChosenFabric chosen = chooseFabric("Swatch", name, panel, {0}, warnings);
        assignWoven(file, {{"Swatch", {{"preset", name}}, "materials.Swatch", ""}});
        EXPECT_EQ(paramsToJson(chosen.params), paramsToJson(file.materials[0].woven.value()));
        EXPECT_TRUE(warnings.empty());
    }
    SceneDescription scene = swatch(dir);
    std::vector<std::string> warnings;
    const ChosenFabric denim = chooseFabric("Swatch", "denim", scene, {0}, warnings);
    // 25 ends and 16 picks per cm over 5 cm; its draft comes with it for the draft view.
    EXPECT_NEAR(denim.params.repeat.x, 125.0f, 1e-3f);
    EXPECT_NEAR(denim.params.repeat.y, 80.0f, 1e-3f);
    EXPECT_NE(denim.wif.find("denim.wif"), std::string::npos);
}

TEST(FabricChoice, MeasuresAreTheLibrarysUntilTheYarnsChange) {
    TempDir dir;
    SceneDescription scene = swatch(dir);
    std::vector<std::string> warnings;
    const ChosenFabric denim = chooseFabric("Swatch", "denim", scene, {0}, warnings);
    const glm::dvec2 metresPerUv(0.05);
    const FabricMeasures library = *measureMaterial(readFabricMaterial("denim", warnings));
    const FabricMeasures panel = measureOnMesh(denim.params, metresPerUv, &denim);
    EXPECT_NEAR(panel.threadsPerCm.x, 25.0, 1e-4);
    EXPECT_NEAR(panel.threadsPerCm.y, 16.0, 1e-4);
    EXPECT_FALSE(panel.weightFromWidths);
    EXPECT_NEAR(panel.gramsPerSquareMetre, library.gramsPerSquareMetre, 1e-6 * library.gramsPerSquareMetre);
    EXPECT_EQ(panel.repeatThreads, library.repeatThreads);
    EXPECT_NEAR(panel.repeatCm.x, 0.16, 1e-5);

    // Twice the repeat: twice the threads per cm; the 6 Ne count no longer describes yarns that
    // kept their width as a fraction of a halved spacing, so the weight comes from the widths.
    WovenParams denser = denim.params;
    denser.repeat *= 2.0f;
    const FabricMeasures d = measureOnMesh(denser, metresPerUv, &denim);
    EXPECT_NEAR(d.threadsPerCm.x, 50.0, 1e-4);
    EXPECT_TRUE(d.weightFromWidths);
    // Yarns of the same fraction of half the spacing: a quarter of the tex, twice the threads.
    EXPECT_NEAR(d.gramsPerSquareMetre, 0.5 * library.gramsPerSquareMetre, 0.01 * library.gramsPerSquareMetre);
    EXPECT_TRUE(measureOnMesh(denim.params, metresPerUv, nullptr).weightFromWidths);
}

TEST(FabricChoice, ThumbnailIsTheDrawdownInThreadColours) {
    std::vector<std::string> warnings;
    // Denim's 4-thread twill: 16 threads of it, 8 pixels each; indigo and ecru, each on top in
    // three of four cells along a row.
    const MaterialJson denim = readFabricMaterial("denim", warnings);
    const Image image = fabricThumbnail(denim, 128);
    ASSERT_EQ(image.width, 128);
    ASSERT_EQ(image.height, 128);
    int warp = 0, weft = 0;
    for (int x = 4; x < 128; x += 8) {
        const glm::vec3 c = image.at(x, 4);
        warp += c == denim.params.warp_color;
        weft += c == denim.params.weft_color;
    }
    EXPECT_EQ(warp + weft, 16);
    EXPECT_EQ(warp, 12);  // 3/1: the warp-faced twill
    // The tartan's sett of 104 threads, one pixel each: all its colours.
    const MaterialJson tartan = readFabricMaterial("tartan", warnings);
    const Image sett = fabricThumbnail(tartan, 128);
    EXPECT_EQ(sett.width, 104);
    std::set<std::tuple<float, float, float>> colours;
    for (const glm::vec3& c : sett.pixels) colours.insert({c.r, c.g, c.b});
    std::set<std::tuple<float, float, float>> threads;
    for (const glm::vec3& c : tartan.params.warp_colors) threads.insert({c.r, c.g, c.b});
    EXPECT_EQ(colours, threads);
}

}  // namespace
}  // namespace woven
