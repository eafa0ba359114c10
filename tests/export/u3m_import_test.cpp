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
#include "frame_io.h"
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
    ExrImage render(const std::string& args, const std::string& out) {
        const test::RunResult r = runWovenCommand("render " + args + " -o '" + file(out) + "' --spp 2 --width 48 --height 36 --no-denoise");
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

TEST_F(U3mImportTest, WovenReadsItsOwnBackAsTheSameClothBitForBit) {
    const std::string u3m = exportDenim();
    const ExrImage original = render("'" + file("denim.json") + "'", "original.exr");
    const ExrImage read = render("'" + drape("read.json", "{\"u3m\": \"denim.u3ma\"}") + "'", "read.exr");
    expectSameRadiance(original, read);
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
