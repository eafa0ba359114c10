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
#include "frame_io.h"
#include "image_io.h"
#include "scene_lighting.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "../common/load_error.h"

namespace woven {
namespace {

using test::loadError;

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using ::testing::Not;
using json = nlohmann::json;

// A triangle seen by a camera on node `cameraNode`, and lit by `lights` (KHR_lights_punctual) on
// a node at `lightPosition`.
std::string writeScene(TempDir& dir, const std::string& name, const json& cameraNode, const json& camera,
                       const json& lights = json::array(), const json& lightPosition = {0, 0, 2}) {
    GltfBuilder b;
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}});
    b.json()["cameras"] = json::array({camera});
    json node = cameraNode;
    node["camera"] = 0;
    std::vector<int> roots{b.addNode({{"mesh", mesh}}), b.addNode(node)};
    if (!lights.empty()) {
        b.useExtension("KHR_lights_punctual");
        b.json()["extensions"]["KHR_lights_punctual"]["lights"] = lights;
        roots.push_back(b.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", lightPosition}}));
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

// Embree aborted the process (an assertion, exit 134) on rays from about 1e19 m (issue 21): every
// position a file gives is held to woven's coordinate limit, 1e12 m, and refused beyond it naming
// the file and what lies there.
TEST(UntrustedValues, PositionsBeyondTheCoordinateLimitAreRefusedNamingWhatLiesThere) {
    TempDir dir;
    const std::string camera = loadError(writeScene(dir, "camera.gltf", {{"name", "far"}, {"translation", {0, 0, 1e19}}}, kCamera));
    EXPECT_THAT(camera, HasSubstr("camera.gltf: node 'far': camera 'camera0' at (0, 0, 1e+19) lies beyond woven's limit of 1e+12 m"));
    const json lamp = json::array({{{"type", "point"}, {"intensity", 100}, {"name", "lamp"}}});
    EXPECT_THAT(loadError(writeScene(dir, "light.gltf", json::object(), kCamera, lamp, {0, 0, 1e20})),
                HasSubstr("light.gltf: node 'node2': light 'lamp' at (0, 0, 1e+20) lies beyond"));
    // A directional light has no position: its node may be anywhere.
    const json sun = json::array({{{"type", "directional"}, {"intensity", 100}}});
    EXPECT_EQ(loadError(writeScene(dir, "sun.gltf", json::object(), kCamera, sun, {0, 0, 1e20})), "(no error)");
    // Just inside the limit is fine.
    EXPECT_EQ(loadError(writeScene(dir, "near.gltf", {{"translation", {0, 0, 1e12}}}, kCamera)), "(no error)");

    // A vertex no triangle uses still stretches the bounds that --camera auto frames; one that a
    // node's transform takes far out is as far.
    GltfBuilder b;
    const int spread = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e30f, 0, 0}})}}},
                                  {"indices", b.addIndices({0, 1, 2})}}, "spread");
    b.setScene({b.addNode({{"mesh", spread}, {"name", "cloth"}})});
    b.writeGltf(dir.file("bounds.gltf"));
    EXPECT_THAT(loadError(dir.file("bounds.gltf")),
                HasSubstr("bounds.gltf: mesh 'cloth/spread/0': vertex 3's world position (1e+30, 0, 0) lies beyond"));
    GltfBuilder moved;
    const int triangle = moved.addMesh({{"attributes", {{"POSITION", moved.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}});
    moved.setScene({moved.addNode({{"mesh", triangle}, {"translation", {0, -2e13, 0}}})});
    moved.writeGltf(dir.file("moved.gltf"));
    EXPECT_THAT(loadError(dir.file("moved.gltf")), HasSubstr("vertex 0's world position (0, -2e+13, 0) lies beyond"));

    writeScene(dir, "cloth.gltf", json::object(), kCamera);
    std::ofstream(dir.file("lamp.json"))
        << R"({"gltf": "cloth.gltf", "lights": [{"type": "point", "position": [0, 0, 1e25], "intensity": 1}]})";
    EXPECT_THAT(loadError(dir.file("lamp.json")), HasSubstr("lamp.json: lights[0].position: (0, 0, 1e+25) lies beyond"));
    std::ofstream(dir.file("target.json")) << R"({"gltf": "cloth.gltf", "camera": {"position": [0, 0, 1], "target": [-1e13, 0, 0]}})";
    EXPECT_THAT(loadError(dir.file("target.json")), HasSubstr("target.json: camera.target: (-1e+13, 0, 0) lies beyond"));
}

// A camera 1e20 m up the z axis looking at the origin was refused as "camera.up: must not be
// parallel to the view direction": the view's squared length overflowed a float. It is refused
// for where it is; views too short for a float's square are cameras like any other.
TEST(UntrustedValues, ACameraFarOrCloseToItsTargetIsJudgedInDouble) {
    TempDir dir;
    writeScene(dir, "cloth.gltf", json::object(), kCamera);
    std::ofstream(dir.file("far.json")) << R"({"gltf": "cloth.gltf", "camera": {"position": [0, 0, 1e20], "target": [0, 0, 0]}})";
    const std::string far = loadError(dir.file("far.json"));
    EXPECT_THAT(far, HasSubstr("far.json: camera.position: (0, 0, 1e+20) lies beyond woven's limit"));
    EXPECT_THAT(far, Not(HasSubstr("parallel")));

    std::ofstream(dir.file("close.json")) << R"({"gltf": "cloth.gltf", "camera": {"position": [0, 0, 1e-20], "target": [0, 0, 0]}})";
    const SceneDescription close = loadScene(dir.file("close.json"));
    EXPECT_EQ(glm::vec3(close.camera.cameraToWorld[0]), glm::vec3(1, 0, 0));
    EXPECT_EQ(glm::vec3(close.camera.cameraToWorld[1]), glm::vec3(0, 1, 0));
    EXPECT_EQ(glm::vec3(close.camera.cameraToWorld[2]), glm::vec3(0, 0, 1));

    // Truly parallel, or no up at all, is still refused.
    for (const auto& [up, problem] : {std::pair{"[0, 0, 5]", "camera.up: must not be parallel"}, {"[0, 0, 0]", "camera.up: must not be zero"}}) {
        std::ofstream(dir.file("up.json")) << R"({"gltf": "cloth.gltf", "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": )"
                                          << up << "}}";
        EXPECT_THAT(loadError(dir.file("up.json")), HasSubstr(problem)) << up;
    }
}

}  // namespace
}  // namespace woven
