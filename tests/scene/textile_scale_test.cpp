// Textile units on a mesh (docs/FABRICS.md): a 5 cm swatch whose UVs span it once carries the
// thread counts it is given, per cm and per inch alike, seen in `repeat` and in the threads the
// material shades; UVs too uneven for one scale warn; bad values name the scene and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "woven_assignment.h"
#include "woven_material.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

constexpr float kSide = 0.05f;  // metres

// A square of `side` metres in the xy plane, UVs 0..1 across it; `stretch` squeezes the UVs of
// its second triangle along u (1: none), for a mapping whose scale varies.
SceneDescription swatch(const TempDir& dir, float stretch = 1.0f) {
    GltfBuilder b;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {kSide, 0, 0}, {kSide, kSide, 0}, {0, 0, 0}, {kSide, kSide, 0}, {0, kSide, 0}};
    const std::vector<glm::vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {stretch, 1}, {0, 1}};
    const int material = b.addMaterial({{"name", "Swatch"}});
    const json primitive = {{"attributes", {{"POSITION", b.addPositions(p)}, {"TEXCOORD_0", b.addVec2(uv)}}},
                            {"material", material}};
    b.setScene({b.addNode({{"name", "Swatch"}, {"mesh", b.addMesh(primitive, "Swatch")}})});
    b.writeGltf(dir.file("swatch.gltf"));
    return loadScene(dir.file("swatch.gltf"));
}

WovenParams assign(SceneDescription& scene, const json& params) {
    assignWoven(scene, {{"Swatch", params, "materials.Swatch", ""}});
    return scene.materials[0].woven.value();
}

std::string error(SceneDescription& scene, const json& params) {
    try {
        assign(scene, params);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// Threads met along a line across the swatch: a single-yarn tile with yarns half their spacing
// wide, so each thread is a run of yarn between see-through gaps. `alongU`: the line runs along
// u (crossing warp ends) at v = 0.5, else along v at u = 0.5: on a cell edge of the other side,
// in the gap between its yarns, so that only the threads counted are seen.
int threadsAcross(const WovenParams& p, bool alongU) {
    const WovenMaterial material(p);
    constexpr int kSamples = 20000;  // 333 samples a thread at 60 threads: no run is missed
    int threads = 0;
    bool inYarn = false;
    for (int i = 0; i < kSamples; ++i) {
        const double t = (i + 0.5) / kSamples;
        ShadingInput in;
        in.uv = alongU ? glm::dvec2(t, 0.5) : glm::dvec2(0.5, t);
        const bool yarn = material.shade(in).has_value();
        threads += yarn && !inYarn;
        inYarn = yarn;
    }
    return threads;
}

TEST(TextileScale, FiveCentimetreSwatchAt8EndsAnd12PicksPerCmHas40By60Threads) {
    TempDir dir;
    for (const json& counts : {json{{"ends_per_cm", 8}, {"picks_per_cm", 12}},
                               json{{"ends_per_inch", 20.32}, {"picks_per_inch", 30.48}}}) {
        SCOPED_TRACE(counts.dump());
        SceneDescription scene = swatch(dir);
        const WovenParams p = assign(scene, counts);
        EXPECT_NEAR(p.repeat.x, 40.0f, 1e-4f);
        EXPECT_NEAR(p.repeat.y, 60.0f, 1e-4f);
        EXPECT_TRUE(scene.warnings.empty());
        json warp = counts, weft = counts;
        warp.update({{"tile", {"|"}}, {"yarn_width", 0.5}, {"warp_width", 0.5}});
        weft.update({{"tile", {"-"}}, {"yarn_width", 0.5}, {"warp_width", 0.5}});
        SceneDescription a = swatch(dir), b = swatch(dir);
        EXPECT_EQ(threadsAcross(assign(a, warp), true), 40);
        EXPECT_EQ(threadsAcross(assign(b, weft), false), 60);
    }
}

// "*" sets both thread counts, "Swatch" only the ends: the ends are Swatch's and the picks the
// broader target's, key by key (it was refused: "'ends_per_cm' needs 'picks_per_cm'"). A repeat
// in the narrower target replaces both counts.
TEST(TextileScale, ANarrowerTargetSettingOneSideKeepsTheBroaderOnesOther) {
    TempDir dir;
    SceneDescription scene = swatch(dir);
    assignWoven(scene, {{"*", {{"ends_per_cm", 8}, {"picks_per_cm", 12}}, "materials.*", ""},
                        {"Swatch", {{"ends_per_inch", 40.64}}, "materials.Swatch", ""}});
    const WovenParams p = scene.materials[0].woven.value();
    EXPECT_NEAR(p.repeat.x, 80.0f, 1e-3f);  // 16 ends per cm over 5 cm
    EXPECT_NEAR(p.repeat.y, 60.0f, 1e-3f);  // 12 picks per cm, from "*"
    SceneDescription replaced = swatch(dir);
    assignWoven(replaced, {{"*", {{"ends_per_cm", 8}, {"picks_per_cm", 12}}, "materials.*", ""},
                           {"Swatch", {{"repeat", {10, 20}}}, "materials.Swatch", ""}});
    EXPECT_EQ(replaced.materials[0].woven->repeat, glm::vec2(10.0f, 20.0f));
}

TEST(TextileScale, UnevenUvsWarnOnce) {
    TempDir dir;
    // The second triangle's UVs squeezed to 0.5 along u: its length per UV unit is twice the first's.
    SceneDescription scene = swatch(dir, 0.5f);
    assign(scene, {{"ends_per_cm", 8}, {"picks_per_cm", 12}});
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_THAT(scene.warnings[0], HasSubstr("materials.Swatch: 'ends_per_cm': the mesh's UVs are too uneven for one physical scale"));
}

TEST(TextileScale, BadValuesNameTheSceneAndTheKey) {
    TempDir dir;
    SceneDescription scene = swatch(dir);
    const std::string where = scene.source + ": materials.Swatch: ";
    EXPECT_THAT(error(scene, {{"ends_per_cm", 0}, {"picks_per_cm", 12}}), HasSubstr(where + "'ends_per_cm' = 0: need a number"));
    EXPECT_THAT(error(scene, {{"ends_per_cm", 8}, {"picks_per_inch", -3}}), HasSubstr(where + "'picks_per_inch' = -3: need"));
    EXPECT_THAT(error(scene, {{"ends_per_cm", 8}, {"picks_per_cm", 12}, {"warp_count", "12 furlongs"}}),
                HasSubstr(where + "'warp_count' = \"12 furlongs\": 'furlongs' is no yarn count unit"));
    EXPECT_THAT(error(scene, {{"ends_per_cm", 8}, {"picks_per_cm", 12}, {"repeat", 40}}),
                HasSubstr(where + "'ends_per_cm' and 'repeat' both set the repeat"));
    EXPECT_THAT(error(scene, {{"ends_per_cm", 8}}), HasSubstr(where + "'ends_per_cm' needs 'picks_per_cm'"));
    EXPECT_THAT(error(scene, {{"warp_count", "20 tex"}}), HasSubstr(where + "'warp_count' needs the thread spacing"));
    EXPECT_THAT(error(scene, {{"ends_per_cm", 8}, {"picks_per_cm", 12}, {"scale", "draft"}}),
                HasSubstr(where + "'ends_per_cm' and 'scale' both set the repeat"));
}

}  // namespace
}  // namespace woven
