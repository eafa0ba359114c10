// Values no one means, in files that parse: a camera scaled to nothing, an aspect ratio below
// zero, lights of infinite or absurd power, an environment image holding infinity. Each would
// render a blank or NaN frame (or make Embree assert); each is refused naming the file and what
// is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "gltf_builder.h"
#include "image_io.h"
#include "scene_lighting.h"
#include "scene_loader.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

std::string loadError(const std::string& path) {
    try {
        loadScene(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// A triangle seen by a camera on node `cameraNode`, and lit by `lights` (KHR_lights_punctual).
std::string writeScene(TempDir& dir, const std::string& name, const json& cameraNode, const json& camera,
                       const json& lights = json::array()) {
    GltfBuilder b;
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}});
    b.json()["cameras"] = json::array({camera});
    json node = cameraNode;
    node["camera"] = 0;
    std::vector<int> roots{b.addNode({{"mesh", mesh}}), b.addNode(node)};
    if (!lights.empty()) {
        b.useExtension("KHR_lights_punctual");
        b.json()["extensions"]["KHR_lights_punctual"]["lights"] = lights;
        roots.push_back(b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0, 2}}}));
    }
    b.setScene(roots);
    b.writeGltf(dir.file(name));
    return dir.file(name);
}

const json kCamera = {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}};

TEST(UntrustedValues, ADegenerateCameraTransformIsRefused) {
    TempDir dir;
    EXPECT_THAT(loadError(writeScene(dir, "zero.gltf", {{"scale", {0, 0, 0}}}, kCamera)),
                HasSubstr("the camera's transform is degenerate"));
    const std::string flat = loadError(writeScene(dir, "flat.gltf", {{"scale", {1, 0, 1}}}, kCamera));
    EXPECT_THAT(flat, HasSubstr("flat.gltf"));
    EXPECT_THAT(flat, HasSubstr("degenerate"));
    // A scaled camera is fine: the scale is dropped, the view kept.
    EXPECT_EQ(loadError(writeScene(dir, "scaled.gltf", {{"scale", {3, 3, 3}}}, kCamera)), "(no error)");
}

TEST(UntrustedValues, AnAspectRatioOutsideReasonIsRefused) {
    TempDir dir;
    for (double aspect : {-1.0, 1e-9, 1e9}) {
        json camera = kCamera;
        camera["perspective"]["aspectRatio"] = aspect;
        const std::string message = loadError(writeScene(dir, "aspect.gltf", json::object(), camera));
        EXPECT_THAT(message, HasSubstr("aspect.gltf")) << aspect;
        EXPECT_THAT(message, HasSubstr("aspectRatio")) << aspect;
    }
}

TEST(UntrustedValues, LightsOfInfiniteOrAbsurdPowerAreRefused) {
    TempDir dir;
    // 1e39 is a finite double but an infinite float; 1e20 cd is no lamp anyone owns.
    for (double intensity : {1e39, 1e20, -5.0}) {
        const std::string message = loadError(writeScene(
            dir, "light.gltf", json::object(), kCamera, json::array({{{"type", "point"}, {"intensity", intensity}}})));
        EXPECT_THAT(message, HasSubstr("light.gltf")) << intensity;
        EXPECT_THAT(message, HasSubstr("intensity")) << intensity;
    }
    const std::string cone = loadError(writeScene(
        dir, "spot.gltf", json::object(), kCamera,
        json::array({{{"type", "spot"}, {"spot", {{"innerConeAngle", 1.0}, {"outerConeAngle", 0.5}}}}})));
    EXPECT_THAT(cone, HasSubstr("cone angles"));
    // A real bright light is fine: a 100 W bulb is about 140 cd; a stage light 1e6.
    EXPECT_EQ(loadError(writeScene(dir, "bright.gltf", json::object(), kCamera,
                                   json::array({{{"type", "point"}, {"intensity", 1e6}}}))),
              "(no error)");
}

TEST(UntrustedValues, SceneFileLightsAndEnvironmentsOfInfinitePowerAreRefused) {
    TempDir dir;
    writeScene(dir, "cloth.gltf", json::object(), kCamera);
    std::ofstream(dir.file("huge.json"))
        << R"({"gltf": "cloth.gltf", "lights": [{"type": "point", "position": [0, 0, 2], "intensity": 1e39}]})";
    EXPECT_THAT(loadError(dir.file("huge.json")), HasSubstr("huge.json"));
    EXPECT_THAT(loadError(dir.file("huge.json")), HasSubstr("intensity"));
    std::ofstream(dir.file("sky.json")) << R"({"gltf": "cloth.gltf", "environment": {"color": [1e30, 1, 1]}})";
    EXPECT_THAT(loadError(dir.file("sky.json")), HasSubstr("environment.color"));

    // An environment image holding infinity: refused naming the file and the pixel.
    ExrImage sky;
    sky.image.width = 4;
    sky.image.height = 2;
    sky.image.pixels.assign(8, glm::vec3(1.0f));
    sky.image.pixels[5].g = std::numeric_limits<float>::infinity();
    writeExr(dir.file("sky.exr"), sky, ExrPrecision::Float);
    try {
        environmentFromOption(dir.file("sky.exr"));
        ADD_FAILURE() << "an infinite environment was accepted";
    } catch (const SceneError& e) {
        EXPECT_THAT(e.what(), HasSubstr("sky.exr: pixel (1, 1) is not finite"));
    }
}

}  // namespace
}  // namespace woven
