// Targets that make parts of a scene woven: by material, mesh or node name (a node's subtree),
// globs and "*" (primitives without a material included), the order in which layers apply,
// shared materials split, and targets that name nothing listing what exists.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "woven_assignment.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// Sofa (node) > Seat (node, mesh "Cushion", material "Velvet")
//             > Back (node, mesh "CushionBack", material "Velvet")
//             > Legs (node, mesh "Legs", material "Wood")
// Shirt (node, mesh "Grid", no material: a simulated cloth)
struct SofaScene {
    TempDir dir;
    SceneDescription scene;
    SofaScene() {
        GltfBuilder b;
        const int velvet = b.addMaterial({{"name", "Velvet"}, {"emissiveFactor", {0.1, 0, 0}}});
        const int wood = b.addMaterial({{"name", "Wood"}});
        const auto mesh = [&](const char* name, int material) {
            json primitive = {{"attributes", {{"POSITION", b.addPositions(kTriangle)}}}};
            if (material >= 0) primitive["material"] = material;
            return b.addMesh(primitive, name);
        };
        const int seat = b.addNode({{"name", "Seat"}, {"mesh", mesh("Cushion", velvet)}});
        const int back = b.addNode({{"name", "Back"}, {"mesh", mesh("CushionBack", velvet)}});
        const int legs = b.addNode({{"name", "Legs"}, {"mesh", mesh("Legs", wood)}});
        const int sofa = b.addNode({{"name", "Sofa"}, {"children", {seat, back, legs}}});
        const int shirt = b.addNode({{"name", "Shirt"}, {"mesh", mesh("Grid", -1)}});
        b.setScene({sofa, shirt});
        b.writeGltf(dir.file("sofa.gltf"));
        scene = loadScene(dir.file("sofa.gltf"));
    }
    const Mesh& mesh(const std::string& name) const {
        for (const Mesh& m : scene.meshes)
            if (m.meshName == name) return m;
        throw std::runtime_error("no mesh " + name);
    }
    const Material& material(const std::string& meshName) const { return scene.materials.at(size_t(mesh(meshName).material)); }
    std::string error(const std::vector<WovenAssignment>& a) {
        try {
            assignWoven(scene, a);
        } catch (const SceneError& e) {
            return e.what();
        }
        return "(no error)";
    }
};

WovenAssignment set(const std::string& target, json params) { return {target, std::move(params), "materials." + target, ""}; }

TEST(WovenAssignment, LoaderRecordsMeshAndNodeNames) {
    SofaScene s;
    EXPECT_EQ(s.mesh("Cushion").nodePath, (std::vector<std::string>{"Sofa", "Seat"}));
    EXPECT_EQ(s.mesh("Grid").nodePath, (std::vector<std::string>{"Shirt"}));
    EXPECT_EQ(s.mesh("Grid").material, -1);
}

TEST(WovenAssignment, StarCoversPrimitivesWithoutAMaterial) {
    SofaScene s;
    assignWoven(s.scene, {set("*", {{"ex", 7}})});
    for (const Mesh& m : s.scene.meshes) {
        ASSERT_GE(m.material, 0) << m.meshName;
        ASSERT_TRUE(s.scene.materials[size_t(m.material)].woven) << m.meshName;
        EXPECT_EQ(s.scene.materials[size_t(m.material)].woven->ex, 7.0f);
    }
    EXPECT_EQ(s.material("Grid").name, "(no material) [*]");
}

TEST(WovenAssignment, MeshTargetSplitsASharedMaterialAndKeepsTheOther) {
    SofaScene s;
    const size_t before = s.scene.materials.size();
    assignWoven(s.scene, {set("mesh:Cushion", {{"pattern", {9, 1, 3}}})});
    ASSERT_TRUE(s.material("Cushion").woven);
    EXPECT_EQ(s.material("Cushion").woven->pattern, glm::ivec3(9, 1, 3));
    EXPECT_EQ(s.material("Cushion").name, "Velvet [mesh:Cushion]");
    EXPECT_EQ(s.material("Cushion").emission, glm::vec3(0.1f, 0, 0));  // the original's other inputs stay
    EXPECT_FALSE(s.material("CushionBack").woven);  // shared the glTF material, unchanged
    EXPECT_EQ(s.material("CushionBack").name, "Velvet");
    EXPECT_EQ(s.scene.materials.size(), before + 1);
}

TEST(WovenAssignment, WholeMaterialChangesInPlace) {
    SofaScene s;
    const size_t before = s.scene.materials.size();
    assignWoven(s.scene, {set("Velvet", {{"ex", 3}})});
    EXPECT_EQ(s.scene.materials.size(), before);
    EXPECT_EQ(s.material("Cushion").name, "Velvet");
    EXPECT_EQ(s.material("CushionBack").woven->ex, 3.0f);
}

TEST(WovenAssignment, NodeTargetCoversItsSubtree) {
    SofaScene s;
    assignWoven(s.scene, {set("node:Sofa", {{"ex", 5}})});
    EXPECT_EQ(s.material("Cushion").woven->ex, 5.0f);
    EXPECT_EQ(s.material("CushionBack").woven->ex, 5.0f);
    EXPECT_EQ(s.material("Legs").woven->ex, 5.0f);
    EXPECT_FALSE(s.mesh("Grid").material >= 0);
}

TEST(WovenAssignment, GlobsMatchNamesAsAShellDoes) {
    SofaScene s;
    assignWoven(s.scene, {set("mesh:Cushion*", {{"ex", 9}})});
    EXPECT_EQ(s.material("Cushion").woven->ex, 9.0f);
    EXPECT_EQ(s.material("CushionBack").woven->ex, 9.0f);
    EXPECT_FALSE(s.material("Legs").woven);
    SofaScene t;
    assignWoven(t.scene, {set("W?od", {{"ex", 2}}), set("material:[V]elvet", {{"ex", 4}})});
    EXPECT_EQ(t.material("Legs").woven->ex, 2.0f);
    EXPECT_EQ(t.material("Cushion").woven->ex, 4.0f);
}

// Every layer applies, least specific first: "*" < material glob < material < mesh glob < mesh
// < node (deeper over shallower, a name over a glob). A key only a less specific target sets
// survives under a more specific one.
TEST(WovenAssignment, MostSpecificTargetWinsKeyByKey) {
    SofaScene s;
    assignWoven(s.scene, {set("node:Seat", {{"ex", 50}}),  // given first, yet most specific
                          set("*", {{"ex", 10}, {"ey", 11}, {"cy", 0.1}}),
                          set("Velvet", {{"ex", 20}, {"ey", 21}}),
                          set("mesh:Cushion", {{"ex", 30}}),
                          set("node:Sofa", {{"ex", 40}, {"noise", 0.3}})});
    const WovenParams& seat = *s.material("Cushion").woven;
    EXPECT_EQ(seat.ex, 50.0f);    // node:Seat, the deepest node
    EXPECT_EQ(seat.ey, 21.0f);    // Velvet over *
    EXPECT_FLOAT_EQ(seat.cy, 0.1f);     // only * sets it
    EXPECT_FLOAT_EQ(seat.noise, 0.3f);  // node:Sofa
    const WovenParams& back = *s.material("CushionBack").woven;
    EXPECT_EQ(back.ex, 40.0f);  // node:Sofa over mesh and material
    EXPECT_EQ(s.material("Legs").woven->ex, 40.0f);
    EXPECT_EQ(s.material("Grid").woven->ex, 10.0f);  // only *
    // Equally specific targets apply in the order given.
    SofaScene t;
    assignWoven(t.scene, {set("mesh:Cushion*", {{"ex", 1}}), set("mesh:Cush*", {{"ex", 2}})});
    EXPECT_EQ(t.material("Cushion").woven->ex, 2.0f);
}

TEST(WovenAssignment, ATargetThatNamesNothingListsWhatExists) {
    SofaScene s;
    const std::string e = s.error({set("mesh:Sheet", json::object())});
    EXPECT_THAT(e, HasSubstr("materials.mesh:Sheet: 'mesh:Sheet' names nothing"));
    EXPECT_THAT(e, HasSubstr("materials 'Velvet', 'Wood'"));
    EXPECT_THAT(e, HasSubstr("meshes 'Cushion', 'CushionBack', 'Grid', 'Legs'"));
    EXPECT_THAT(e, HasSubstr("nodes 'Back', 'Legs', 'Seat', 'Shirt', 'Sofa'"));
    EXPECT_THAT(s.error({set("Velvet", {{"cy", 3}})}), HasSubstr("materials.Velvet: "));
    EXPECT_THAT(SofaScene().error({set("node:Shirt", {{"colour", 1}})}), HasSubstr("unknown woven material field 'colour'"));
}

TEST(WovenAssignment, CommandLineForm) {
    SofaScene s;
    const WovenAssignment a = parseWovenOption(s.scene, "node:Shirt={\"pattern\":[1,2,1]}");
    EXPECT_EQ(a.target, "node:Shirt");
    EXPECT_EQ(a.where, "--woven node:Shirt");
    assignWoven(s.scene, {a});
    EXPECT_EQ(s.material("Grid").woven->pattern, glm::ivec3(1, 2, 1));
    EXPECT_THROW(parseWovenOption(s.scene, "Shirt"), SceneError);
    EXPECT_THROW(parseWovenOption(s.scene, "Shirt={bad"), SceneError);
}

}  // namespace
}  // namespace woven
