// A bare fabric where `woven export` and `woven share` take a scene: a library fabric's name, a
// fabric file, a woven material's JSON, a WIF draft or a U3M, each laid on woven's drape with the
// default scene's camera and named after the fabric; a scene file is still a scene; anything else
// refused by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../common/run_woven.h"
#include "fabric_scene.h"
#include "scene_loader.h"

namespace woven {
namespace {

class FabricSceneTest : public test::CommandTest {};

// The scene's woven materials by name.
std::vector<std::string> wovenNames(const SceneDescription& scene) {
    std::vector<std::string> names;
    for (const Material& m : scene.materials)
        if (m.woven) names.push_back(m.name);
    return names;
}

TEST_F(FabricSceneTest, EachFormOfAFabricLiesOnTheDrape) {
    const std::string assets = WOVEN_ASSETS_DIR;
    std::ofstream(file("red.json")) << R"({"weft_color": [0.7, 0.05, 0.05], "ends_per_cm": 30, "picks_per_cm": 30})";
    const std::vector<std::pair<std::string, std::string>> forms = {{"denim", "denim"},
                                                                    {assets + "/fabrics/satin_charmeuse.json", "satin_charmeuse"},
                                                                    {file("red.json"), "red"},
                                                                    {assets + "/drafts/houndstooth.wif", "houndstooth"}};
    const SceneDescription drape = loadScene(assets + "/default_scene.json");
    for (const auto& [argument, name] : forms) {
        SCOPED_TRACE(argument);
        const SceneDescription scene = loadSceneOrFabric(argument);
        EXPECT_EQ(wovenNames(scene), std::vector<std::string>{name});
        EXPECT_EQ(scene.meshes.size(), drape.meshes.size());
        EXPECT_TRUE(scene.hasCamera);
        EXPECT_EQ(scene.camera.cameraToWorld, drape.camera.cameraToWorld);
        EXPECT_FALSE(scene.lightingFromSceneFile);  // the studio light woven gives a scene without any
    }
    // The draft at its own thread count: 20 per cm on the drape, as the library's houndstooth.
    const SceneDescription draft = loadSceneOrFabric(assets + "/drafts/houndstooth.wif");
    const SceneDescription library = loadSceneOrFabric("houndstooth");
    for (const Material& m : draft.materials)
        if (m.woven)
            for (const Material& l : library.materials)
                if (l.woven) EXPECT_EQ(m.woven->repeat, l.woven->repeat);
    // A scene file is the scene it says.
    EXPECT_EQ(wovenNames(loadSceneOrFabric(assets + "/default_scene.json")), std::vector<std::string>{"Cloth"});
}

TEST_F(FabricSceneTest, WhatIsNoFabricIsRefusedByNameAndNothingIsWritten) {
    std::ofstream(file("notes.txt")) << "hello";
    // A draft that gives no thread spacing has no real size to lay it on the drape at.
    std::ifstream draft(std::string(WOVEN_ASSETS_DIR) + "/drafts/houndstooth.wif");
    std::ofstream unspaced(file("unspaced.wif"));
    for (std::string line; std::getline(draft, line);)
        if (line.rfind("Spacing=", 0) != 0) unspaced << line << "\n";
    unspaced.close();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"no_such_fabric", "no_such_fabric: no such file, nor a fabric of the library (woven fabrics lists them)"},
        {file("notes.txt"), "notes.txt: unknown scene file type '.txt'"},
        {file("missing.wif"), "missing.wif"},
        {file("unspaced.wif"), "unspaced.wif: the draft gives no warp spacing"},
    };
    for (const auto& [argument, message] : cases)
        for (const std::string command : {"share '" + argument + "' -o '" + file("page") + "'",
                                          "export '" + argument + "' -o '" + file("x.u3ma") + "'"}) {
            const test::RunResult r = test::runWovenCommand(command);
            EXPECT_NE(r.exitCode, 0) << command;
            EXPECT_NE(r.out.find(message), std::string::npos) << command << ": " << r.out;
            EXPECT_FALSE(std::filesystem::exists(file("page")));
            EXPECT_FALSE(std::filesystem::exists(file("x.u3ma")));
        }
}

}  // namespace
}  // namespace woven
