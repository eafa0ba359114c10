// woven's frame EXRs as other readers take them: every channel half or float and named as
// compositors name layers (R, G, B, then layer.pass.channel), so that Blender and Nuke read the
// beauty and the render passes; and, where Blender is installed, Blender opens a rendered and a
// merged frame at their size with the beauty woven reads (tools/blender_exr_check.py).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <string>

#include "frame_io.h"
#include "image_io.h"
#include "../common/run_woven.h"

namespace {

using woven::test::runWovenCommand;

class ExrReaders : public woven::test::CommandTest {
protected:
    std::string render(const std::string& name, int first, int spp) {
        const std::string path = file(name);
        const std::string scene = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
        const auto r = runWovenCommand("render " + scene + " --width 24 --height 18 --integrator bdpt --seed 5 --first-sample " +
                                       std::to_string(first) + " --spp " + std::to_string(spp) + " -o " + path);
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return path;
    }

    // Every channel's name and type as OpenEXR's own library reads them, not woven's code.
    static std::map<std::string, Imf::PixelType> channels(const std::string& path) {
        std::map<std::string, Imf::PixelType> found;
        const Imf::InputFile in(path.c_str());
        for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) found[c.name()] = c.channel().type;
        return found;
    }

    // What readers accept: half or float channels, the beauty as R, G, B and the rest as
    // layer.pass.channel with a one-letter channel (Blender reads no other token there, and
    // skips unsigned integer channels only to fail reading the file: issue 24's 0 x 0 image).
    static void expectReadable(const std::string& path, const std::set<std::string>& layers) {
        const std::regex layered("[A-Za-z][A-Za-z0-9_]*(\\.[A-Za-z][A-Za-z0-9_]*)*\\.[A-Z]");
        std::set<std::string> names, found;
        for (const auto& [name, type] : channels(path)) {
            names.insert(name);
            EXPECT_TRUE(type == Imf::HALF || type == Imf::FLOAT) << path << ": " << name << " is of OpenEXR type " << type;
            EXPECT_TRUE(name == "R" || name == "G" || name == "B" || std::regex_match(name, layered)) << path << ": " << name;
            if (const size_t dot = name.rfind('.'); dot != std::string::npos) found.insert(name.substr(0, dot));
        }
        for (const char* c : {"R", "G", "B"}) EXPECT_TRUE(names.count(c)) << path << " has no " << c;
        for (const std::string& layer : layers) EXPECT_TRUE(found.count(layer)) << path << " has no layer " << layer;
    }
};

const std::set<std::string> kPasses = {"albedo", "normal", "depth", "variance", "samples"};

TEST_F(ExrReaders, RenderedAndMergedFramesHaveOnlyChannelsReadersAccept) {
    const std::string a = render("a.exr", 0, 1), b = render("b.exr", 1, 1);
    ASSERT_EQ(runWovenCommand("merge " + a + " " + b + " -o " + file("m.exr")).exitCode, 0);
    expectReadable(a, kPasses);
    expectReadable(file("m.exr"), kPasses);
    for (const char* c : {"albedo.B", "normal.X", "normal.Z", "depth.Z", "variance.G", "samples.N"})
        EXPECT_TRUE(channels(a).count(c)) << a << " has no " << c;

    // A denoised frame keeps its noisy beauty as a layer beside the passes.
    woven::ExrImage frame = woven::readExr(a);
    frame.noisy = frame.image;
    for (glm::vec3& p : frame.image.pixels) p *= 0.5f;
    woven::writeExr(file("denoised.exr"), frame, woven::ExrPrecision::Half);
    std::set<std::string> withNoisy = kPasses;
    withNoisy.insert("noisy");
    expectReadable(file("denoised.exr"), withNoisy);
    const woven::ExrImage back = woven::readExr(file("denoised.exr"));
    ASSERT_TRUE(back.noisy);
    EXPECT_EQ(back.noisy->pixels.size(), frame.noisy->pixels.size());
    EXPECT_EQ(back.passSums, frame.passSums);
}

// A command's standard output (standard error too) and exit status.
woven::test::RunResult shell(const std::string& command) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return {"", -1};
    std::string out;
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    const int status = pclose(pipe);
    return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

TEST_F(ExrReaders, BlenderOpensRenderedAndMergedFramesAtTheirSizeWithTheBeauty) {
    if (shell("command -v blender").exitCode != 0) GTEST_SKIP() << "Blender is not installed (apt-get install blender)";
    const std::string a = render("a.exr", 0, 1), b = render("b.exr", 1, 1), all = render("all.exr", 0, 2);
    ASSERT_EQ(runWovenCommand("merge " + a + " " + b + " -o " + file("m.exr")).exitCode, 0);
    const auto r = shell("timeout 120 blender -b --factory-startup --python '" + std::string(WOVEN_TOOLS_DIR) +
                         "/blender_exr_check.py' -- " + all + " 24 18 " + file("all_blender.exr") + " " + file("m.exr") +
                         " 24 18 " + file("m_blender.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    for (const std::string& frame : {all, file("m.exr")}) {
        const size_t line = r.out.find(frame + ": passes Combined,Alpha,");
        ASSERT_NE(line, std::string::npos) << r.out;
        const std::string passes = r.out.substr(line, r.out.find('\n', line) - line) + ",";
        for (const char* pass : {"albedo", "depth", "normal", "samples", "variance"})
            EXPECT_THAT(passes, testing::HasSubstr(std::string(",") + pass + ",")) << frame;
        const std::string opened = frame.substr(0, frame.size() - 4) + "_blender.exr";
        const woven::ExrImage ours = woven::readExr(frame), blenders = woven::readExr(opened);
        ASSERT_EQ(blenders.image.width, 24) << opened;
        ASSERT_EQ(blenders.image.height, 18) << opened;
        // Blender's compositor passes float pixels through untouched: equal bit for bit.
        EXPECT_EQ(blenders.image.pixels, ours.image.pixels) << opened;
    }
}

}  // namespace
