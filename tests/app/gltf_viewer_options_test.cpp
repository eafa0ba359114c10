// `woven render` on glTF files as glTF viewers show them, in files the test writes: a missing
// texture file is a warning (an error with --strict), the back of a single-sided surface is not
// seen by the camera, --camera chooses among the file's cameras, and --list says what is there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../scene/gltf_builder.h"
#include "frame_io.h"
#include "image_io.h"
#include "../common/run_woven.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using json = nlohmann::json;
using woven::test::GltfBuilder;

using Result = woven::test::RunResult;
Result run(const std::string& args) { return woven::test::runWovenCommand(args); }

constexpr const char* kFrame = " --width 16 --height 12 --spp 2 --integrator path --environment 0";

double meanLuminance(const std::string& exr) {
    const woven::Image image = woven::readExr(exr).image;
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels) sum += woven::luminance(p);
    return sum / double(image.pixels.size());
}

// A quad in the plane z = `z`, 2 * half on a side, counter-clockwise (its front) seen from +z,
// or from -z when `facingBack`.
int addQuad(GltfBuilder& b, float z, float half, int material, bool facingBack = false) {
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
    if (facingBack) indices = {0, 2, 1, 0, 3, 2};
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{-half, -half, z}, {half, -half, z},
                                                                               {half, half, z}, {-half, half, z}})}}},
                                {"indices", b.addIndices(indices)},
                                {"material", material}},
                               material == 0 ? "LampQuad" : "CardQuad");
    return b.addNode({{"mesh", mesh}});
}

// A glowing double-sided quad at z = 0, a point light behind it, and two cameras at z = 5:
// "Away" (camera 0) looks down +z at nothing, "Front" (camera 1) at the lamp. With `card`, a black
// quad at z = 2 fills the view of "Front", single- or double-sided, its front towards the camera or
// away from it; nothing lights its side towards the camera.
struct Card {
    bool doubleSided = false, facingCamera = false;
};
void writeScene(const std::string& path, const std::optional<Card>& card = std::nullopt) {
    GltfBuilder b;
    b.addMaterial({{"name", "Lamp"}, {"emissiveFactor", {1, 1, 1}}, {"doubleSided", true}});
    b.addMaterial({{"name", "Black"},
                   {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}}},
                   {"doubleSided", card && card->doubleSided}});
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"name", "Bulb"}, {"intensity", 683}}};
    b.json()["cameras"] = {{{"name", "Away"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
                           {{"name", "Front"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
    std::vector<int> roots = {
        b.addNode({{"name", "AwayNode"}, {"camera", 0}, {"translation", {0, 0, 5}}, {"rotation", {0, 1, 0, 0}}}),
        b.addNode({{"name", "FrontNode"}, {"camera", 1}, {"translation", {0, 0, 5}}}),
        b.addNode({{"name", "BulbNode"}, {"translation", {0, 3, -3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}),
        addQuad(b, 0.0f, 1.0f, 0)};
    if (card) roots.push_back(addQuad(b, 2.0f, 3.0f, 1, !card->facingCamera));
    b.setScene(roots);
    b.writeGltf(path);
}

class GltfViewerOptions : public woven::test::CommandTest {
protected:
    // The mean of the frame `woven render SCENE OPTIONS` writes; -1 when it fails.
    double frame(const std::string& scene, const std::string& options) {
        const std::string out = file("out.exr");
        fs::remove(out);
        const Result r = run("render " + scene + kFrame + " " + options + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return r.exitCode == 0 ? meanLuminance(out) : -1.0;
    }
};

TEST_F(GltfViewerOptions, CameraChoosesByIndexNameOrNodeOrFramesTheScene) {
    writeScene(file("two.gltf"));
    EXPECT_EQ(frame(file("two.gltf"), ""), 0.0);  // the first camera looks away
    for (const std::string choice : {"1", "Front", "FrontNode", "auto"})
        EXPECT_GT(frame(file("two.gltf"), "--camera " + choice), 0.05) << choice;
    EXPECT_EQ(frame(file("two.gltf"), "--camera Away"), 0.0);

    const Result bad = run("render " + file("two.gltf") + kFrame + " --camera 5 -o " + file("bad.exr"));
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_THAT(bad.out, HasSubstr(file("two.gltf") + ": --camera 5: no such camera; its cameras are 0 'Away' (node "
                                      "'AwayNode'), 1 'Front' (node 'FrontNode'), or auto"));
    EXPECT_FALSE(fs::exists(file("bad.exr")));
}

TEST_F(GltfViewerOptions, ListPrintsCamerasMaterialsMeshesAndLightsAndRendersNothing) {
    writeScene(file("two.gltf"), Card{});
    const Result r = run("render " + file("two.gltf") + " --list");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("cameras:\n  0  'Away'  node 'AwayNode'\n  1  'Front'  node 'FrontNode'\n"));
    EXPECT_THAT(r.out, HasSubstr("materials:\n  'Lamp'  glTF\n  'Black'  glTF\n"));
    EXPECT_THAT(r.out, HasSubstr("meshes:\n  'node3/LampQuad/0'  2 triangles  material 'Lamp'  emissive\n"
                                    "  'node4/CardQuad/0'  2 triangles  material 'Black'\n"));
    EXPECT_THAT(r.out, HasSubstr("lights:\n  point  'Bulb'  intensity 1 1 1 W/sr\n"));
    EXPECT_FALSE(fs::exists("two.exr"));  // no frame, not even under the default name
    EXPECT_THAT(r.out, Not(HasSubstr("wrote")));
}

// glTF viewers cull the back of a single-sided surface: the camera sees the lamp through it.
TEST_F(GltfViewerOptions, CameraSeesThroughTheBackOfSingleSidedSurfaces) {
    const auto through = [&](Card card) {
        const std::string scene = file("card.gltf");
        writeScene(scene, card);
        return frame(scene, "--camera Front");
    };
    EXPECT_GT(through({false, false}), 0.05);  // its back: culled, the lamp shows
    EXPECT_EQ(through({false, true}), 0.0);    // its black front
    EXPECT_EQ(through({true, false}), 0.0);    // double-sided: its black back
    EXPECT_EQ(through({true, true}), 0.0);
}

// A scene with one texture file gone (a folder copied without it) renders with a warning naming
// it, as glTF viewers and Blender draw it; --strict refuses it. A file that is there but broken
// is refused either way.
TEST_F(GltfViewerOptions, MissingTextureFileIsAWarningUnlessStrictAndBrokenOnesStayErrors) {
    const auto write = [&](const std::string& name, const std::string& image) {
        GltfBuilder b;
        b.json()["images"] = {{{"uri", image}}};
        b.json()["textures"] = {{{"source", 0}}};
        b.addMaterial({{"name", "Lamp"}, {"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}}});
        b.json()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
        const int quad = addQuad(b, 0.0f, 1.0f, 0);
        b.setScene({quad, b.addNode({{"camera", 0}, {"translation", {0, 0, 5}}})});
        b.writeGltf(file(name));
        return file(name);
    };
    const std::string missing = write("missing.gltf", "gone.png");
    const std::string out = file("out.exr");
    const Result warned = run("render " + missing + kFrame + " -o " + out);
    ASSERT_EQ(warned.exitCode, 0) << warned.out;
    EXPECT_THAT(warned.out, HasSubstr("warning: " + missing + ": material 'Lamp'.emissiveTexture: texture file "
                                         "'gone.png' does not exist (looked in '" + dir_.string() +
                                         "'); drawn without it (--strict makes this an error)\n"));
    EXPECT_GT(meanLuminance(out), 0.05);  // the emissive factor alone, as under a white texture

    const Result strict = run("render " + missing + kFrame + " --strict -o " + file("strict.exr"));
    EXPECT_NE(strict.exitCode, 0);
    EXPECT_THAT(strict.out, HasSubstr(missing + ": material 'Lamp'.emissiveTexture: texture file 'gone.png' does not exist"));
    EXPECT_FALSE(fs::exists(file("strict.exr")));

    std::ofstream(file("junk.png")) << "not a png at all";
    const Result corrupt = run("render " + write("corrupt.gltf", "junk.png") + kFrame + " -o " + file("corrupt.exr"));
    EXPECT_NE(corrupt.exitCode, 0);
    EXPECT_THAT(corrupt.out, HasSubstr("junk.png': the image is an unknown format"));
    EXPECT_FALSE(fs::exists(file("corrupt.exr")));
}

}  // namespace
