// Preview screenshots of the procedural cloth with each weave preset (and a few parameter
// sets), compared with committed golden PNGs. Regenerate them after an intended change with
//   WOVEN_UPDATE_GOLDEN=1 ctest -R GoldenScreenshots
// (writes tests/preview/golden/*.png in the source tree), then look at them before committing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "demo_scene.h"
#include "gl_test_context.h"
#include "display_transform.h"
#include "image_io.h"
#include "weave_presets.h"

namespace woven::test {
namespace {

struct GoldenCase {
    std::string name;
    WovenParams params;
};
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

// "satin (9,1,3)" -> "satin_9_1_3"
std::string fileName(const std::string& presetName) {
    std::string out;
    for (char ch : presetName) {
        if (std::isalnum(static_cast<unsigned char>(ch))) out += ch;
        else if (!out.empty() && out.back() != '_') out += '_';
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

std::vector<GoldenCase> goldenCases() {
    std::vector<GoldenCase> cases;
    for (const WeavePreset& preset : weavePresets()) {
        GoldenCase c{preset.name, demoClothParams()};
        applyPreset(preset, c.params);
        c.name = fileName(preset.name);
        cases.push_back(c);
    }
    GoldenCase far{"far_field_filter", demoClothParams()};
    far.params.repeat = glm::vec2(500.0f);
    GoldenCase shiny{"anisotropic_backing", demoClothParams()};
    shiny.params.ex = 3000.0f;
    shiny.params.ey = 3.0f;
    shiny.params.rs = 0.2f;
    shiny.params.cy = 1.0f;
    shiny.params.crimp = 0.6f;
    shiny.params.yarn_width = 0.7f;
    shiny.params.warp_width = 0.6f;
    shiny.params.backing = 1;
    shiny.params.backing_color = glm::vec3(0.02f, 0.1f, 0.02f);
    cases.push_back(far);
    cases.push_back(shiny);
    return cases;
}

class GoldenScreenshots : public testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenScreenshots, MatchCommittedPng) {
    const int w = 160, h = 120;
    const std::string golden = std::string(WOVEN_GOLDEN_DIR) + "/" + GetParam().name + ".png";
    // Named by process too: two builds' suites may run at once on one machine.
    const std::string shot =
        testing::TempDir() + "woven_preview_" + GetParam().name + "_" + std::to_string(::getpid()) + ".png";
    writePng(shot, previewRadiance(wavyClothScene(GetParam().params), w, h), {0.0f, ToneMap::Clamp});
    if (std::getenv("WOVEN_UPDATE_GOLDEN")) {
        std::filesystem::copy_file(shot, golden, std::filesystem::copy_options::overwrite_existing);
        GTEST_SKIP() << "wrote " << golden;
    }
    ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing: see the comment at the top of this file";
    // Linear decoding gives the 8-bit codes / 255.
    const Image expected = readImage(golden, ChannelEncoding::Linear);
    const Image got = readImage(shot, ChannelEncoding::Linear);
    ASSERT_EQ(got.width, expected.width);
    ASSERT_EQ(got.height, expected.height);
    // Tolerance: a channel may differ by up to 2 codes anywhere (float rounding of another
    // llvmpipe build or CPU's vector width); more than that in at most 0.5 % of the pixels
    // (pixels straddling an element edge may flip yarn); the mean difference stays under
    // 0.5 codes. A changed weave, colour or light moves far more pixels than that.
    size_t bad = 0;
    double sum = 0.0;
    for (size_t i = 0; i < got.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(got.pixels[i] - expected.pixels[i]) * 255.0f;
        sum += (d.x + d.y + d.z) / 3.0;
        bad += std::fmax(d.x, std::fmax(d.y, d.z)) > 2.5f;
    }
    EXPECT_LE(double(bad), 0.005 * double(got.pixels.size())) << GetParam().name;
    EXPECT_LT(sum / double(got.pixels.size()), 0.5) << GetParam().name;
    if (!HasFailure()) std::filesystem::remove(shot);  // kept to look at when it differs
}

INSTANTIATE_TEST_SUITE_P(Presets, GoldenScreenshots, testing::ValuesIn(goldenCases()),
                         [](const testing::TestParamInfo<GoldenCase>& info) { return info.param.name; });

}  // namespace
}  // namespace woven::test
