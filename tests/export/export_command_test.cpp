// `woven export` and `woven bake` as a user runs them: the exported satin of assets/, a gingham
// whose yarns transmit and the bake's sample file pass Khronos's glTF validator (gltf-transform
// from npm; skipped, saying how to get it, where it is not installed), and bad input gets a clear
// message and leaves no file.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../common/run_woven.h"
#include "gltf_loader.h"
#include "gltf_writer.h"
#include "scene_camera.h"
#include "srgb.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::runWoven;
using test::TempDir;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The validator's path: $GLTF_TRANSFORM, else what CMake found; empty when neither runs.
std::string validator() {
    const char* env = std::getenv("GLTF_TRANSFORM");
    const std::string path = env && *env ? env : GLTF_TRANSFORM;
    return !path.empty() && ::access(path.c_str(), X_OK) == 0 ? path : "";
}

struct Validation {
    int errors = 0, warnings = 0;
    std::string report;
};

// Runs gltf-transform's validate (the Khronos glTF-Validator) on `file` and counts its issues
// by severity (0 error, 1 warning, 2 info, 3 hint; CSV: code,message,severity,pointer).
Validation validate(const std::string& file) {
    Validation v;
    const std::string command = "timeout 120 " + quoted(validator()) + " validate " + quoted(file) + " --format csv 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[4096];
    size_t n;
    while (pipe && (n = fread(buffer, 1, sizeof buffer, pipe)) > 0) v.report.append(buffer, n);
    if (pipe) pclose(pipe);
    std::istringstream lines(v.report);
    for (std::string line; std::getline(lines, line);) {
        // The message may hold commas: severity is the field before the last.
        const size_t last = line.rfind(','), before = last == std::string::npos || last == 0 ? std::string::npos : line.rfind(',', last - 1);
        if (before == std::string::npos) continue;
        const std::string severity = line.substr(before + 1, last - before - 1);
        v.errors += severity == "0";
        v.warnings += severity == "1";
    }
    return v;
}

// The mean colour of an sRGB texture, in linear light.
glm::vec3 meanLinearColour(const TextureImage& t) {
    glm::dvec3 sum(0.0);
    for (const glm::u8vec4& b : t.bytes) sum += glm::dvec3(srgbToLinear(b.r / 255.0f), srgbToLinear(b.g / 255.0f), srgbToLinear(b.b / 255.0f));
    return glm::vec3(sum / double(std::max<size_t>(t.bytes.size(), 1)));
}

#define REQUIRE_VALIDATOR()                                                                                       \
    if (validator().empty())                                                                                      \
    GTEST_SKIP() << "Khronos's glTF validator is not installed, so the exported files were not validated: "     \
                    "npm install --prefix ~ @gltf-transform/cli (or set GLTF_TRANSFORM to its gltf-transform)"

TEST(ExportCommand, TheExportedSatinPassesKhronossValidator) {
    REQUIRE_VALIDATOR();
    TempDir dir;
    const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/paper_d_satin.json";
    for (const std::string& options : {std::string("-o ") + quoted(dir.file("satin.glb")),
                                       "-o " + quoted(dir.file("satin.gltf")) + " --keep-woven --size 256"}) {
        SCOPED_TRACE(options);
        const auto r = runWoven("export " + quoted(scene) + " " + options + " 2>&1");
        ASSERT_EQ(r.exitCode, 0) << r.out;
    }
    for (const char* name : {"satin.glb", "satin.gltf"}) {
        const Validation v = validate(dir.file(name));
        std::printf("[ validator ] %s: %d errors, %d warnings\n", name, v.errors, v.warnings);
        EXPECT_NE(v.report.find("code,message,severity,pointer"), std::string::npos) << "the validator did not run:\n" << v.report;
        EXPECT_EQ(v.errors, 0) << v.report;
        EXPECT_EQ(v.warnings, 0) << v.report;
    }
}

TEST(ExportCommand, YarnTransmissionIsWrittenAsDiffuseTransmissionAndPassesKhronossValidator) {
    // A red satin whose yarns pass 80 % (MODEL_TRANSMISSION.md 1): T = t (1 - R_d) (R_d / max R_d)^2
    // per channel, so the baked colour is red and T's red 0.8 (1 - 0.55) = 0.36, within the far
    // field's mixing of both faces' yarns. Without transmission no extension.
    TempDir dir;
    const std::string scene = quoted(std::string(WOVEN_ASSETS_DIR) + "/paper_d_satin.json");
    const std::string red = R"("pattern": [9, 1, 3], "weft_color": [0.55, 0.12, 0.1], "warp_color": [0.55, 0.12, 0.1])";
    const auto r = runWoven("export " + scene + " --woven 'Cloth={" + red + ", \"transmission\": 0.8}' --size 128 -o " +
                            quoted(dir.file("sheer.gltf")) + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("baked as KHR_materials_diffuse_transmission"), std::string::npos) << r.out;
    const SceneDescription sheer = loadGltf(dir.file("sheer.gltf"));
    const auto cloth = std::find_if(sheer.materials.begin(), sheer.materials.end(), [](const Material& m) { return m.name == "Cloth"; });
    ASSERT_NE(cloth, sheer.materials.end());
    // T per texel is the factor times the colour texture (the factor the largest texel's T, which
    // the satin's colour noise lifts above the mean): over the texels, the mean T (8-bit sRGB
    // rounds G's 0.034 by 0.001 at most).
    EXPECT_EQ(cloth->diffuseTransmission.color, glm::vec3(1.0f));
    ASSERT_TRUE(cloth->diffuseTransmission.colorTexture);
    const glm::vec3 T = cloth->diffuseTransmission.factor *
                        meanLinearColour(sheer.textures.at(size_t(cloth->diffuseTransmission.colorTexture.image)));
    EXPECT_NEAR(T.r, 0.36f, 0.01f);
    EXPECT_NEAR(T.g, 0.8f * 0.88f * (0.12f / 0.55f) * (0.12f / 0.55f), 0.003f);
    EXPECT_GE(cloth->diffuseTransmission.factor, T.r);
    EXPECT_EQ(cloth->alphaMode, AlphaMode::Opaque);  // a gap-free satin: alpha stays for gaps only
    const auto opaque = runWoven("export " + scene + " --woven 'Cloth={" + red + "}' --size 128 -o " + quoted(dir.file("opaque.gltf")) + " 2>&1");
    ASSERT_EQ(opaque.exitCode, 0) << opaque.out;
    std::ifstream in(dir.file("opaque.gltf"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("KHR_materials_diffuse_transmission"), std::string::npos);
    if (validator().empty()) return;
    const Validation v = validate(dir.file("sheer.gltf"));
    EXPECT_NE(v.report.find("code,message,severity,pointer"), std::string::npos) << "the validator did not run:\n" << v.report;
    EXPECT_EQ(v.errors, 0) << v.report;
    EXPECT_EQ(v.warnings, 0) << v.report;
}

TEST(ExportCommand, StripedYarnTransmissionIsATexturePerTexelAndPassesKhronossValidator) {
    // Gingham's dark and light threads with their yarns passing 80 %: T = t (1 - R_d) (R_d /
    // max R_d)^2 is several times larger for the dark thread than for the light one, and a
    // crossing passes the smaller of its two yarns' T, so the texels of dark-on-dark crossings
    // must come out far brighter than the others, the brightest at the factor itself.
    TempDir dir;
    const std::string scene = quoted(std::string(WOVEN_ASSETS_DIR) + "/gingham.json");
    const auto r = runWoven("export " + scene + " --woven 'Cloth={\"transmission\": 0.8}' --size 128 -o " +
                            quoted(dir.file("gingham.gltf")) + " 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const SceneDescription gingham = loadGltf(dir.file("gingham.gltf"));
    const auto cloth = std::find_if(gingham.materials.begin(), gingham.materials.end(), [](const Material& m) { return m.name == "Cloth"; });
    ASSERT_NE(cloth, gingham.materials.end());
    ASSERT_TRUE(cloth->diffuseTransmission.colorTexture);
    const TextureImage& t = gingham.textures.at(size_t(cloth->diffuseTransmission.colorTexture.image));
    ASSERT_FALSE(t.bytes.empty());
    float brightest = 0.0f, darkest = 1.0f;
    for (const glm::u8vec4& b : t.bytes) {
        const float peak = srgbToLinear(std::max({b.r, b.g, b.b}) / 255.0f);
        brightest = std::max(brightest, peak);
        darkest = std::min(darkest, peak);
    }
    EXPECT_NEAR(brightest, 1.0f, 0.01f);  // the factor is the largest texel's T
    EXPECT_LT(darkest, 0.5f * brightest) << "one colour for every texel: the stripes' transmission is lost";
    if (validator().empty()) return;
    const Validation v = validate(dir.file("gingham.gltf"));
    EXPECT_NE(v.report.find("code,message,severity,pointer"), std::string::npos) << "the validator did not run:\n" << v.report;
    EXPECT_EQ(v.errors, 0) << v.report;
    EXPECT_EQ(v.warnings, 0) << v.report;
}

TEST(ExportCommand, BakeWritesTheMapsAndASampleFileOtherToolsRead) {
    TempDir dir;
    const auto r = runWoven("bake " + quoted(std::string(WOVEN_ASSETS_DIR) + "/paper_c_twill.json") + " -o " +
                            quoted(dir.path().string()) + " --size 128 --mips 2>&1");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const char* map : {"base_color", "normal", "metallic_roughness", "anisotropy"}) {
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("Cloth_") + map + ".png"))) << map;
        EXPECT_TRUE(std::filesystem::exists(dir.file(std::string("Cloth_") + map + "_mip1.png"))) << map;
    }
    const SceneDescription sample = loadGltf(dir.file("Cloth.gltf"));
    ASSERT_EQ(sample.meshes.size(), 1u);
    EXPECT_TRUE(sample.materials.at(0).anisotropy.texture);
    if (validator().empty()) return;
    const Validation v = validate(dir.file("Cloth.gltf"));
    EXPECT_EQ(v.errors, 0) << v.report;
    EXPECT_EQ(v.warnings, 0) << v.report;
}

TEST(ExportCommand, ASceneWithNothingWovenGetsAClearMessageAndNoFile) {
    TempDir dir;
    SceneDescription plain;
    Mesh quad;
    quad.name = quad.meshName = "Quad";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    quad.triangles = {{0, 1, 2}};
    plain.meshes = {quad};
    std::vector<std::string> warnings;
    writeGltf(dir.file("plain.glb"), plain, sceneCamera(plain), warnings);
    const auto r = runWoven("export " + quoted(dir.file("plain.glb")) + " -o " + quoted(dir.file("out.glb")) + " 2>&1");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.out.find(dir.file("plain.glb") + ": no part of the scene is woven"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--woven TARGET=JSON"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.glb")));
    // Made woven on the command line, it exports.
    const auto made = runWoven("export " + quoted(dir.file("plain.glb")) + " --woven '*={\"repeat\": [40, 40]}' -o " +
                               quoted(dir.file("out.glb")) + " --size 64 2>&1");
    EXPECT_EQ(made.exitCode, 0) << made.out;
    EXPECT_TRUE(std::filesystem::exists(dir.file("out.glb")));
}

TEST(ExportCommand, AnUnwritablePathGetsAClearMessageAndNoFile) {
    TempDir dir;
    const std::string scene = quoted(std::string(WOVEN_ASSETS_DIR) + "/paper_d_satin.json");
    const auto missing = runWoven("export " + scene + " -o " + quoted(dir.file("missing/out.glb")) + " 2>&1");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.out.find(dir.file("missing/out.glb") + ": cannot write in the folder"), std::string::npos) << missing.out;
    const auto extension = runWoven("export " + scene + " -o " + quoted(dir.file("out.usd")) + " 2>&1");
    EXPECT_EQ(extension.exitCode, 1);
    EXPECT_NE(extension.out.find("must end in .glb or .gltf"), std::string::npos) << extension.out;
    const auto bake = runWoven("bake " + scene + " -o " + quoted(dir.file("nowhere")) + " 2>&1");
    EXPECT_EQ(bake.exitCode, 1);
    EXPECT_NE(bake.out.find(dir.file("nowhere") + ": no such folder"), std::string::npos) << bake.out;
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// An output never replaces an input: export onto its own glTF file (through another spelling of
// the path, and onto the glTF a scene file names) and render onto one of the scene's files.
TEST(ExportCommand, AnOutputThatIsAnInputIsRefusedAndTheInputKept) {
    TempDir dir;
    SceneDescription plain;
    Mesh quad;
    quad.name = quad.meshName = "Quad";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    quad.uvs = {{0, 0}, {1, 0}, {1, 1}};
    quad.triangles = {{0, 1, 2}};
    plain.meshes = {quad};
    std::vector<std::string> warnings;
    writeGltf(dir.file("scene.gltf"), plain, sceneCamera(plain), warnings);
    const auto before = std::filesystem::file_size(dir.file("scene.gltf"));
    const std::string woven = " --woven '*={\"repeat\": [40, 40]}' --size 16 2>&1";
    const auto self = runWoven("export " + quoted(dir.file("scene.gltf")) + " -o " + quoted(dir.file("./scene.gltf")) + woven);
    EXPECT_EQ(self.exitCode, 1);
    EXPECT_NE(self.out.find("writing it would replace what it reads"), std::string::npos) << self.out;
    std::ofstream(dir.file("scene.json")) << R"({"gltf": "scene.gltf", "environment": {"color": [1, 1, 1]}})";
    const auto named = runWoven("export " + quoted(dir.file("scene.json")) + " -o " + quoted(dir.file("scene.gltf")) + woven);
    EXPECT_EQ(named.exitCode, 1);
    EXPECT_NE(named.out.find(dir.file("scene.gltf") + ": is an input"), std::string::npos) << named.out;
    const auto render = runWoven("render " + quoted(dir.file("scene.json")) + " -o " + quoted(dir.file("scene.json.png")) +
                                 " --spp 1 --width 8 --height 8 2>&1");
    EXPECT_EQ(render.exitCode, 0) << render.out;  // a new file beside the inputs is fine
    EXPECT_EQ(std::filesystem::file_size(dir.file("scene.gltf")), before);
}

}  // namespace
}  // namespace woven
