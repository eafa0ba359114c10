// The one output rule (output_path.h) as each command that writes meets it: an output naming a
// FIFO or a read-only file is refused and left as it was (as root too: the atomic write's rename
// once replaced /dev/full), and no output may be a file the command read (its scene's texture,
// an environment image). Each refusal names the file, exits non-zero, and writes nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../scene/gltf_builder.h"
#include "image_io.h"
#include "../common/run_woven.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using woven::test::RunResult;

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class OutputPolicy : public woven::test::CommandTest {
protected:
    const std::string scene_ = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    const std::string small_ = " --width 8 --height 6 --spp 1 ";

    // A FIFO and a read-only file, each refused as `command`'s output (its last word) and left as
    // they were.
    void expectRefused(const std::string& command, const std::string& extension) {
        const std::string fifo = file("fifo" + extension), kept = file("kept" + extension);
        ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
        std::ofstream(kept) << "earlier";
        fs::permissions(kept, fs::perms::owner_read | fs::perms::group_read);
        RunResult r = woven::test::runWovenCommand(command + " '" + fifo + "'");
        EXPECT_NE(r.exitCode, 0) << command;
        EXPECT_THAT(r.out, HasSubstr(fifo + ": is not a regular file (a FIFO, socket or device)"));
        EXPECT_TRUE(fs::is_fifo(fifo)) << command;
        r = woven::test::runWovenCommand(command + " '" + kept + "'");
        EXPECT_NE(r.exitCode, 0) << command;
        EXPECT_THAT(r.out, HasSubstr(kept + ": is read-only"));
        EXPECT_EQ(readText(kept), "earlier") << command;
        fs::remove(fifo);
        fs::remove(kept);
    }

    // A quad whose base colour is the texture file tex.png.
    std::string texturedScene() {
        woven::TextureImage texture;
        texture.width = texture.height = 2;
        texture.bytes.assign(4, glm::u8vec4(200, 120, 40, 255));
        woven::writeTexturePng(file("tex.png"), texture);
        woven::test::GltfBuilder b;
        const int positions = b.addPositions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
        const int uv = b.addVec2({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
        const int material = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
        b.json()["images"] = {{{"uri", "tex.png"}}};
        b.json()["textures"] = {{{"source", 0}}};
        const int mesh = b.addMesh({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uv}}},
                                    {"indices", b.addIndices({0, 1, 2, 0, 2, 3})},
                                    {"material", material}});
        b.setScene({b.addNode({{"mesh", mesh}})});
        b.writeGltf(file("textured.gltf"));
        return file("textured.gltf");
    }
};

TEST_F(OutputPolicy, EveryCommandRefusesAFifoAndAReadOnlyFile) {
    expectRefused("render " + scene_ + small_ + "-o", ".exr");
    expectRefused("bsdf-plot --size 16 -o", ".png");
    expectRefused("export " + scene_ + " --size 16 -o", ".glb");
    expectRefused("preview --headless " + scene_ + small_ + "--screenshot", ".png");
}

TEST_F(OutputPolicy, NoOutputIsAFileTheCommandRead) {
    const std::string scene = texturedScene();
    const std::string texture = readText(file("tex.png"));
    for (const std::string& command : {"render " + scene + small_ + "-o ", "preview --headless " + scene + small_ + "--screenshot "}) {
        const RunResult r = woven::test::runWovenCommand(command + file("tex.png"));
        EXPECT_NE(r.exitCode, 0) << command;
        EXPECT_THAT(r.out, HasSubstr(file("tex.png") + ": is an input of this command"));
    }
    EXPECT_EQ(readText(file("tex.png")), texture);
    // An environment image is an input too.
    const RunResult r =
        woven::test::runWovenCommand("render " + scene + small_ + "--environment " + file("tex.png") + " -o " + file("tex.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr(file("tex.png") + ": is an input of this command"));
    EXPECT_EQ(readText(file("tex.png")), texture);
}

TEST_F(OutputPolicy, ABakeIsWrittenWholeOrNotAtAll) {
    const std::string bake = "bake " + std::string(WOVEN_ASSETS_DIR) + "/paper_c_twill.json --size 16 -o ";
    std::ofstream(file("a_file")) << "x";
    RunResult r = woven::test::runWovenCommand(bake + file("a_file"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr(file("a_file") + ": is a file: bake -o names the folder"));
    // A folder holding an earlier bake, one of whose files cannot be replaced: nothing new is
    // written beside the old files.
    fs::create_directory(file("earlier"));
    std::ofstream(file("earlier/Cloth_normal.png")) << "earlier";
    fs::permissions(file("earlier/Cloth_normal.png"), fs::perms::owner_read);
    r = woven::test::runWovenCommand(bake + file("earlier"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("Cloth_normal.png: is read-only"));
    EXPECT_EQ(std::distance(fs::directory_iterator(file("earlier")), fs::directory_iterator()), 1);
}

TEST_F(OutputPolicy, HeadlessPreviewRefusesTheWindowsOptions) {
    for (const std::string& option : {"--frames 3", "--window-screenshot w.png", "--wif d.wif"}) {
        const RunResult r = woven::test::runWovenCommand("preview --headless " + scene_ + small_ + "--screenshot " +
                                                         file("s.png") + " " + option);
        EXPECT_NE(r.exitCode, 0) << option;
        EXPECT_THAT(r.out, HasSubstr(option.substr(0, option.find(' ')) + " is for the previewer's window"));
        EXPECT_FALSE(fs::exists(file("s.png")));
    }
}

TEST_F(OutputPolicy, BsdfEvalRefusesAnUnknownKeyAndBsdfPlotAnotherImageTypeButTakesAPreset) {
    std::ofstream(file("query.jsonl")) << R"({"material": {}, "UV": [0.3, 0.3], "wi": [0, 0, 1], "wo": [0, 0, 1]})" << "\n";
    RunResult r = woven::test::runWovenCommand("bsdf-eval < " + file("query.jsonl"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("unknown key \\\"UV\\\""));
    r = woven::test::runWovenCommand("bsdf-plot --size 16 -o " + file("plot.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("plot.exr: bsdf-plot writes PNG"));
    EXPECT_FALSE(fs::exists(file("plot.exr")));
    // bsdf-plot reads bsdf-eval's names, "preset" included.
    r = woven::test::runWovenCommand("bsdf-plot --size 16 --material '{\"preset\": \"denim\"}' -o " + file("denim.png"));
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(fs::exists(file("denim.png")));
}

}  // namespace
