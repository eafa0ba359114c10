// woven reads a U3M as a material for any mesh (a scene file's "u3m", --woven TARGET=FILE.u3ma):
// its own back as the same woven cloth, rendered bit for bit as the scene it was exported from;
// another tool's (here woven's file without its custom section) as a textured material whose
// textures span their size in mm on the mesh, so the cloth keeps its real thread count; bad files
// refused by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../common/run_woven.h"
#include "file_reading.h"
#include "flat_cloth.h"
#include "frame_io.h"
#include "gltf_writer.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "u3ma_archive.h"

namespace woven {
namespace {

using nlohmann::json;
using test::runWovenCommand;

class U3mImportTest : public test::CommandTest {
protected:
    const std::string camera = R"("camera": {"position": [0.05, 1.1, 0.95], "target": [0.0, 0.72, 0.5], "yfov_degrees": 9})";
    std::string drape(const std::string& name, const std::string& material) {
        const std::string path = file(name);
        std::ofstream(path) << "{\"gltf\": \"" << WOVEN_ASSETS_DIR << "/cloth_drape.glb\", \"materials\": {\"Cloth\": " << material
                            << "}, " << camera << "}";
        return path;
    }
    // The path tracer named: auto picks an integrator by a timed pilot, so two renders of one
    // scene may differ with the machine's load.
    ExrImage render(const std::string& args, const std::string& out,
                    const std::string& frame = "--spp 2 --width 48 --height 36 --integrator path") {
        const test::RunResult r = runWovenCommand("render " + args + " -o '" + file(out) + "' " + frame + " --no-denoise");
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return readExr(file(out));
    }
    std::string exportDenim() {
        const std::string out = file("denim.u3ma");
        const test::RunResult r = runWovenCommand("export '" + drape("denim.json", R"({"preset": "denim"})") + "' -o '" + out +
                                                  "' --size 64 --preview-size 0");
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return out;
    }
};

void expectSameRadiance(const ExrImage& a, const ExrImage& b) {
    ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.image.pixels.size(); ++i) differ += a.image.pixels[i] != b.image.pixels[i];
    EXPECT_EQ(differ, 0u) << "pixels differ";
}

// The library's denim and satin, and a WIF draft given bare to `woven export` (laid on the same
// drape at the draft's threads per cm), each read back from its U3M.
TEST_F(U3mImportTest, WovenReadsItsOwnBackAsTheSameClothBitForBit) {
    const std::string wif = std::string(WOVEN_ASSETS_DIR) + "/drafts/houndstooth.wif";
    const std::vector<std::pair<std::string, std::string>> fabrics = {
        {"denim", R"({"preset": "denim"})"}, {"satin_charmeuse", R"({"preset": "satin_charmeuse"})"}, {"houndstooth", R"({"wif": ")" + wif + R"(", "scale": "draft"})"}};
    for (const auto& [name, material] : fabrics) {
        SCOPED_TRACE(name);
        const std::string scene = drape(name + ".json", material);
        const std::string exported = name == "houndstooth" ? wif : scene;
        const test::RunResult r = runWovenCommand("export '" + exported + "' -o '" + file(name + ".u3ma") + "' --size 64 --preview-size 0");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const ExrImage original = render("'" + scene + "'", name + ".exr");
        const ExrImage read = render("'" + drape("read.json", "{\"u3m\": \"" + name + ".u3ma\"}") + "'", "read.exr");
        expectSameRadiance(original, read);
    }
    const std::string u3m = file("denim.u3ma");
    // The command line's --woven takes the file as a scene file's "u3m" does.
    const std::string glb = std::string("'") + WOVEN_ASSETS_DIR + "/cloth_drape.glb' --camera auto";
    const ExrImage preset = render(glb + " --woven 'Cloth={\"preset\":\"denim\"}'", "preset.exr");
    const ExrImage option = render(glb + " --woven 'Cloth=" + u3m + "'", "option.exr");
    expectSameRadiance(preset, option);
}

TEST_F(U3mImportTest, AnotherToolsU3mIsATexturedMaterialAtItsRealSize) {
    // woven's file without its custom section is what any other tool's U3M is to woven.
    std::vector<ArchiveEntry> entries = unpackU3ma(readRegularFile(exportDenim(), size_t(1) << 30), "denim.u3ma", size_t(1) << 30);
    for (ArchiveEntry& e : entries)
        if (e.name == "denim.u3m") {
            json d = json::parse(e.bytes.begin(), e.bytes.end());
            d["custom"] = nullptr;
            const std::string text = d.dump();
            e.bytes.assign(text.begin(), text.end());
        }
    const std::vector<unsigned char> zip = packU3ma(entries, 0);
    std::ofstream(file("other.u3ma"), std::ios::binary).write(reinterpret_cast<const char*>(zip.data()), std::streamsize(zip.size()));

    const SceneDescription woven = loadScene(file("denim.json"));
    const SceneDescription other = loadScene(drape("other.json", R"({"u3m": "other.u3ma"})"));
    const auto cloth = [](const SceneDescription& s) -> const Material& {
        for (const Material& m : s.materials)
            if (m.name == "Cloth") return m;
        throw std::runtime_error("no Cloth");
    };
    const Material& m = cloth(other);
    ASSERT_FALSE(m.woven);
    ASSERT_TRUE(m.baseColorTexture);
    ASSERT_TRUE(m.normalTexture);
    ASSERT_TRUE(m.metallicRoughnessTexture);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);  // the gaps
    // One texture spans one repeat, 4 x 4 threads: the woven cloth's threads per uv unit over 4.
    const glm::vec2 repeat = cloth(woven).woven->repeat;
    EXPECT_NEAR(m.baseColorTexture.uvTransform[0][0], repeat.x / 4.0f, 1e-5 * repeat.x);
    EXPECT_NEAR(m.baseColorTexture.uvTransform[1][1], repeat.y / 4.0f, 1e-5 * repeat.y);
    EXPECT_EQ(m.normalTexture.uvTransform, m.baseColorTexture.uvTransform);
    render("'" + file("other.json") + "'", "other.exr");
}

// Pearson's correlation of two renders' luminance, pixel by pixel: near 1 where the same weave lies
// in the same place, near 0 where one is another size.
double correlation(const ExrImage& a, const ExrImage& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double n = double(a.image.pixels.size());
    for (size_t i = 0; i < a.image.pixels.size(); ++i) {
        const double x = glm::dot(a.image.pixels[i], glm::vec3(0.2126f, 0.7152f, 0.0722f));
        const double y = glm::dot(b.image.pixels[i], glm::vec3(0.2126f, 0.7152f, 0.0722f));
        sa += x, sb += y, saa += x * x, sbb += y * y, sab += x * y;
    }
    return (sab - sa * sb / n) / std::sqrt((saa - sa * sa / n) * (sbb - sb * sb / n));
}

// The issue's check of the real size, with woven as the other tool: a 10 cm plane (uv 0 to 1 over
// it, as a garment tool's flattened pattern piece has some scale of its own) under another tool's
// U3M, each map spanning its `width` x `height` mm on the plane, lies thread on thread with woven's
// own render of the denim at its 25 x 16 threads per cm, seen from 10 cm above over 1.2 cm; the
// same U3M with its maps' mm doubled (the size a tool that ignored them might give) does not.
// Measured over seeds 1 to 3: correlation 0.971 to 0.973 at the real size, 0.022 to 0.033 doubled.
TEST_F(U3mImportTest, AnotherToolsU3mLiesThreadOnThreadWithTheWovenClothOnATenCentimetrePlane) {
    SceneDescription plane;
    plane.meshes = {flatCloth(glm::vec2(0.1f), "Cloth")};
    for (glm::vec2& uv : plane.meshes[0].uvs) uv *= 10.0f;
    plane.materials.resize(1);
    plane.materials[0].name = "Cloth";
    std::vector<std::string> warnings;
    writeGltf(file("plane.gltf"), plane, sceneCamera(plane), warnings);
    const auto scene = [&](const std::string& name, const std::string& material) {
        std::ofstream(file(name)) << R"({"gltf": "plane.gltf", "materials": {"Cloth": )" << material
                                  << R"(}, "camera": {"position": [0, 0.1, 0], "target": [0, 0, 0], "up": [0, 0, -1], "yfov_degrees": 6.9}})";
        return "'" + file(name) + "'";
    };
    ASSERT_EQ(runWovenCommand("export " + scene("denim_plane.json", R"({"preset": "denim"})") + " -o '" + file("denim.u3ma") +
                              "' --size 128 --preview-size 0")
                  .exitCode,
              0);
    // Another tool's U3M: woven's without its custom section; and the same with its maps twice as large.
    for (const double scale : {1.0, 2.0}) {
        std::vector<ArchiveEntry> entries = unpackU3ma(readRegularFile(file("denim.u3ma"), size_t(1) << 30), "denim.u3ma", size_t(1) << 30);
        for (ArchiveEntry& e : entries)
            if (e.name == "denim.u3m") {
                json d = json::parse(e.bytes.begin(), e.bytes.end());
                d["custom"] = nullptr;
                for (auto& [key, value] : d["material"]["front"].items())
                    if (value.is_object() && value.contains("texture") && value["texture"].is_object())
                        for (const char* side : {"width", "height"}) value["texture"]["image"][side] = scale * value["texture"]["image"][side].get<double>();
                const std::string text = d.dump();
                e.bytes.assign(text.begin(), text.end());
            }
        const std::vector<unsigned char> zip = packU3ma(entries, 0);
        std::ofstream(file("other" + std::to_string(int(scale)) + ".u3ma"), std::ios::binary)
            .write(reinterpret_cast<const char*>(zip.data()), std::streamsize(zip.size()));
    }
    for (const int seed : {1, 2, 3}) {
        const std::string frame = "--spp 4 --width 96 --height 96 --integrator path --seed " + std::to_string(seed);
        const ExrImage woven = render(scene("denim_plane.json", R"({"preset": "denim"})"), "woven.exr", frame);
        const ExrImage real = render(scene("real.json", R"({"u3m": "other1.u3ma"})"), "real.exr", frame);
        const ExrImage doubled = render(scene("doubled.json", R"({"u3m": "other2.u3ma"})"), "doubled.exr", frame);
        EXPECT_GT(correlation(woven, real), 0.5);
        EXPECT_LT(correlation(woven, doubled), 0.2);
    }
}

TEST_F(U3mImportTest, BadFilesAreRefusedByName) {
    std::ofstream(file("broken.u3ma")) << "not a zip";
    for (const auto& [material, message] : std::vector<std::pair<std::string, std::string>>{
             {R"({"u3m": "broken.u3ma"})", "broken.u3ma: not a U3MA archive"},
             {R"({"u3m": "missing.u3ma"})", "missing.u3ma"},
             {R"({"u3m": 3})", "'u3m' must be the path"}}) {
        const test::RunResult r = runWovenCommand("render '" + drape("bad.json", material) + "' -o '" + file("bad.png") + "' --spp 1 --width 8 --height 8");
        EXPECT_NE(r.exitCode, 0) << material;
        EXPECT_NE(r.out.find(message), std::string::npos) << material << ": " << r.out;
        EXPECT_NE(r.out.find("materials.Cloth"), std::string::npos) << r.out;
        EXPECT_FALSE(std::filesystem::exists(file("bad.png")));
    }
}

}  // namespace
}  // namespace woven
