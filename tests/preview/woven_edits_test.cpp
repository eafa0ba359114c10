// The previewer's selection and "make woven": a click picks the primitive core's renderer sees
// under the cursor (ScenePicker, the window's code path), WovenEdits turns a target into woven
// cloth on exactly the part it names and back, and what the window saves renders, through
// `woven render`'s RenderJob, exactly as the window's own scene does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../scene/gltf_builder.h"
#include "../scene/temp_dir.h"
#include "material_file.h"
#include "orbit_camera.h"
#include "render_job.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "scene_picker.h"
#include "woven_assignment.h"
#include "woven_edits.h"

namespace woven::test {
namespace {

using json = nlohmann::json;

std::string readText(const std::string& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Three quads side by side facing +z: "Left" and "Middle" share material "Shared [a]" (a name
// with glob characters), "Right" has no material; Left and Middle hang under node "Group".
struct ThreeQuads {
    TempDir dir;
    std::string path;
    SceneDescription scene;
    ThreeQuads() {
        GltfBuilder b;
        const int shared = b.addMaterial({{"name", "Shared [a]"}});
        const auto quad = [&](const char* name, float x, int material) {
            const std::vector<glm::vec3> p = {{x - 0.4f, -0.4f, 0}, {x + 0.4f, -0.4f, 0}, {x + 0.4f, 0.4f, 0}, {x - 0.4f, 0.4f, 0}};
            const std::vector<glm::vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            json primitive = {{"attributes", {{"POSITION", b.addPositions(p)}, {"TEXCOORD_0", b.addVec2(uv)}}},
                              {"indices", b.addIndices({0, 1, 2, 0, 2, 3})}};
            if (material >= 0) primitive["material"] = material;
            return b.addNode({{"name", name}, {"mesh", b.addMesh(primitive, name)}});
        };
        const int left = quad("Left", -1.0f, shared), middle = quad("Middle", 0.0f, shared);
        const int group = b.addNode({{"name", "Group"}, {"children", {left, middle}}});
        b.setScene({group, quad("Right", 1.0f, -1)});
        path = dir.file("quads.gltf");
        b.writeGltf(path);
        scene = loadScene(path);
        scene.environment.color = glm::vec3(1.0f);
    }
    int mesh(const std::string& name) const {
        for (size_t i = 0; i < scene.meshes.size(); ++i)
            if (scene.meshes[i].meshName == name) return int(i);
        return -1;
    }
};

// The window's click: the preview's camera with the window's aspect, the cursor in window pixels.
int clickAt(const SceneDescription& scene, glm::vec2 cursor, glm::ivec2 window) {
    Camera camera = OrbitCamera::forScene(scene).camera();
    camera.aspect = float(window.x) / float(window.y);
    ScenePicker picker;
    return picker.pick(scene, camera, window, cursor);
}

TEST(WovenEdits, AClickPicksWhatIsUnderTheCursor) {
    ThreeQuads q;
    const glm::ivec2 window(300, 200);
    // The scene is framed centred: the middle quad is under the window's centre, the others
    // left and right of it; a corner of the window sees nothing.
    EXPECT_EQ(clickAt(q.scene, {150, 100}, window), q.mesh("Middle"));
    EXPECT_EQ(clickAt(q.scene, {150 - 55, 100}, window), q.mesh("Left"));
    EXPECT_EQ(clickAt(q.scene, {150 + 55, 100}, window), q.mesh("Right"));
    EXPECT_EQ(clickAt(q.scene, {2, 2}, window), -1);
}

TEST(WovenEdits, TargetsOfAPickedPrimitiveLeastSpecificFirst) {
    ThreeQuads q;
    WovenEdits edits(q.scene);
    EXPECT_EQ(edits.targetsFor(q.mesh("Middle")),
              (std::vector<std::string>{"*", "Shared \\[a]", "mesh:Middle", "node:Group", "node:Middle"}));
    EXPECT_EQ(edits.targetsFor(q.mesh("Right")), (std::vector<std::string>{"*", "mesh:Right", "node:Right"}));
}

TEST(WovenEdits, MakeWovenChangesExactlyTheNamedPartAndRevertRestoresIt) {
    ThreeQuads q;
    WovenEdits edits(q.scene);
    const auto woven = [&](const char* mesh) {
        const int m = edits.scene().meshes[size_t(q.mesh(mesh))].material;
        return m >= 0 && edits.scene().materials[size_t(m)].woven.has_value();
    };
    // The middle quad alone, though it shares its glTF material with the left one.
    const int middle = edits.makeWoven("mesh:Middle");
    EXPECT_TRUE(woven("Middle"));
    // New cloth gets 2 mm elements: the quad is 0.8 m per uv unit, so 400 per unit.
    EXPECT_NEAR(edits.params(middle).repeat.x, 400.0f, 1e-2f);
    EXPECT_FALSE(woven("Left"));
    EXPECT_FALSE(woven("Right"));
    // The material name with brackets is a literal target, not a glob.
    edits.makeWoven(edits.targetsFor(q.mesh("Left"))[1]);
    EXPECT_TRUE(woven("Left"));
    // A mesh without a material, through its node.
    edits.makeWoven("node:Right");
    EXPECT_TRUE(woven("Right"));
    // Tuning one edit: the most specific wins on its part.
    edits.params(middle).ex = 777.0f;
    edits.apply();
    EXPECT_EQ(edits.scene().materials[size_t(edits.scene().meshes[size_t(q.mesh("Middle"))].material)].woven->ex, 777.0f);
    EXPECT_NE(edits.scene().materials[size_t(edits.scene().meshes[size_t(q.mesh("Left"))].material)].woven->ex, 777.0f);

    EXPECT_TRUE(edits.revert("node:Right"));
    EXPECT_FALSE(woven("Right"));
    EXPECT_EQ(edits.scene().meshes[size_t(q.mesh("Right"))].material, -1);
    EXPECT_FALSE(edits.revert("node:Right"));
    EXPECT_THROW(edits.makeWoven("mesh:Nothing"), SceneError);
}

// The window's "make woven" keeps the glTF colour, as scene files and --woven do: an orange
// material becomes orange yarns, not woven's red and beige.
TEST(WovenEdits, MakeWovenStartsFromTheMaterialsBaseColour) {
    ThreeQuads q;
    const glm::vec3 orange(0.8f, 0.3f, 0.05f);
    q.scene.materials[0].baseColor = glm::vec4(orange, 1.0f);
    WovenEdits edits(q.scene);
    const int edit = edits.makeWoven("mesh:Middle");
    EXPECT_EQ(edits.params(edit).warp_color, orange);
    EXPECT_EQ(edits.params(edit).weft_color, orange);
    const Material& made = edits.scene().materials[size_t(edits.scene().meshes[size_t(q.mesh("Middle"))].material)];
    EXPECT_EQ(made.woven->weft_color, orange);
    // A primitive without a material has no colour to keep: woven's defaults.
    const int bare = edits.makeWoven("node:Right");
    EXPECT_EQ(edits.params(bare).weft_color, WovenParams{}.weft_color);
}

FilmImage render(const SceneDescription& scene) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 16;
    settings.spp = 2;
    settings.integrator = "path";
    settings.seed = 5;
    RenderJob job(std::make_shared<const SceneDescription>(scene), settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    return job.snapshot();
}

TEST(WovenEdits, WhatTheWindowSavesRendersAsTheWindowsScene) {
    ThreeQuads q;
    WovenEdits edits(q.scene);
    edits.params(edits.makeWoven("node:Group")).pattern = {1, 2, 1};
    edits.params(edits.makeWoven("mesh:Right")).weft_color = {0.1f, 0.7f, 0.2f};
    edits.apply();
    // "Save materials": every edit under its target, in a scene file naming the glTF.
    const std::string saved = q.dir.file("saved.json");
    for (const WovenEdit& e : edits.edits()) saveMaterial(saved, e.target, e.params, q.path);
    SceneDescription reloaded = loadScene(saved);
    reloaded.environment.color = glm::vec3(1.0f);
    const FilmImage a = render(edits.scene()), b = render(reloaded);
    EXPECT_TRUE(a.radiance.pixels == b.radiance.pixels) << "the saved scene renders differently from the window's";
    double sum = 0.0;
    for (const glm::vec3& p : a.radiance.pixels) sum += p.g;
    EXPECT_GT(sum, 0.0);
}

// Save from the window: a scene file copied from the one opened (its paths rebased to the new
// folder), with a moved view and the Render button's settings, renders as the Render button does:
// through renderCamera()'s cameraOf(viewOf()), at the saved noise threshold, bit for bit.
TEST(WovenEdits, ASavedSceneFileRendersAsTheRenderButton) {
    ThreeQuads q;
    const std::string opened = q.dir.file("opened.json");
    {
        std::ofstream out(opened);
        out << json{{"gltf", "quads.gltf"}, {"environment", {{"color", {0.5, 0.5, 0.5}}}}}.dump();
    }
    WovenEdits edits(loadScene(opened));
    edits.params(edits.makeWoven("node:Group")).pattern = {1, 3, 1};
    edits.apply();

    Camera moved = lookAt({0.3f, 0.2f, 2.1f}, {0.05f, -0.1f, 0.0f}, {0.1f, 1.0f, 0.0f}, 0.7f);
    SceneSave save;
    for (const WovenEdit& e : edits.edits()) save.materials.emplace_back(e.target, e.params);
    save.camera = viewOf(moved);
    save.render.noiseThreshold = 0.037;
    save.render.spp = 3;
    std::filesystem::create_directories(q.dir.file("elsewhere"));
    const std::string saved = q.dir.file("elsewhere/tuned.json");
    saveScene(saved, opened, save);
    saveScene(saved, opened, save);  // again: overwritten the same way

    SceneDescription reloaded = loadScene(saved);
    EXPECT_EQ(reloaded.environment.color, glm::vec3(0.5f)) << "the opened scene file's keys were not kept";
    ASSERT_TRUE(reloaded.render.noiseThreshold);
    EXPECT_EQ(*reloaded.render.noiseThreshold, 0.037);
    EXPECT_EQ(defaultRenderSettings(reloaded).spp, 3);
    const Camera button = cameraOf(viewOf(moved));
    EXPECT_TRUE(reloaded.camera.cameraToWorld == button.cameraToWorld && reloaded.camera.yfov == button.yfov)
        << "the saved view is not the Render button's camera";

    SceneDescription window = edits.scene();
    window.camera = button;
    window.hasCamera = true;
    const FilmImage a = render(window), b = render(reloaded);
    EXPECT_TRUE(a.radiance.pixels == b.radiance.pixels) << "the saved scene renders differently from the window's";
}

// Save As: never over a file the scene reads, nor into a name or a file that is not a woven scene
// file (each refused in a message naming the path, the file untouched); over a woven scene file
// it starts anew as the opened scene, not keeping the old file's glTF.
TEST(WovenEdits, SaveAsRefusesTheScenesInputsAndReplacesAnOldSceneFile) {
    ThreeQuads q;
    const std::string opened = q.dir.file("opened.json");
    {
        std::ofstream out(opened);
        out << json{{"gltf", "quads.gltf"}}.dump();
    }
    SceneDescription scene = loadScene(opened);
    SceneSave save;
    save.materials.emplace_back("node:Group", WovenParams{});
    save.inputs = scene.inputFiles;
    save.startAnew = true;
    const auto refused = [&](const std::string& path, const std::string& why) {
        const std::string before = readText(path);
        try {
            saveScene(path, opened, save);
            ADD_FAILURE() << path << " was written";
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": " + why, 0), 0u) << e.what();
        }
        EXPECT_EQ(readText(path), before) << path << " changed";
    };
    refused(opened, "the scene reads this file");
    refused(q.path, "the scene reads this file");
    const std::string image = q.dir.file("render.png");
    std::ofstream(image) << "not a scene";
    refused(image, "not a woven scene file name");
    const std::string other = q.dir.file("other.json");
    std::ofstream(other) << json{{"pattern", {1, 2, 1}}}.dump();
    refused(other, "not a woven scene file");

    const std::string old = q.dir.file("old.json");
    std::ofstream(old) << json{{"gltf", "elsewhere.gltf"}, {"lights", json::array()}}.dump();
    saveScene(old, opened, save);
    const json written = json::parse(readText(old));
    EXPECT_EQ(written["gltf"], "quads.gltf");
    EXPECT_FALSE(written.contains("lights")) << "Save As kept the old file's keys";
}

}  // namespace
}  // namespace woven::test
