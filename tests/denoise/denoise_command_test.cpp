// The denoiser in the commands: `woven render` denoises its frame unless --no-denoise, the EXR
// keeping the noisy beauty as noisy.R/G/B, and `woven merge` denoises the merged sums once, giving
// the frame one render of all the samples gives. --no-passes leaves out the denoiser's guides,
// and so the denoiser.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../common/run_woven.h"
#include "frame_io.h"

namespace woven {
namespace {

class DenoiseCommand : public test::CommandTest {
protected:
    // The default scene (the denim draped, its weave finer than a pixel here) small and short,
    // with the path tracer unless `options` names another: auto's choice is timed, so two renders
    // under load could choose differently, and the frames they compare would differ.
    ExrImage render(const std::string& name, const std::string& options) {
        const std::string out = file(name);
        const std::string integrator = options.find("--integrator") == std::string::npos ? "--integrator path " : "";
        const test::RunResult r = test::runWovenCommand("render '" WOVEN_ASSETS_DIR "/default_scene.json' --width 48 --height 36 " +
                                                        integrator + options + " -o '" + out + "'");
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return readExr(out);
    }
};

TEST_F(DenoiseCommand, RenderDenoisesByDefaultAndKeepsTheNoisyBeauty) {
    const ExrImage denoised = render("denoised.exr", "--spp 4");
    const ExrImage plain = render("plain.exr", "--spp 4 --no-denoise");
    ASSERT_TRUE(denoised.noisy.has_value());
    EXPECT_FALSE(plain.noisy.has_value());
    // The noisy layer is the frame as rendered, bit for bit.
    ASSERT_EQ(denoised.noisy->pixels.size(), plain.image.pixels.size());
    size_t changed = 0;
    for (size_t i = 0; i < plain.image.pixels.size(); ++i) {
        ASSERT_EQ(denoised.noisy->pixels[i], plain.image.pixels[i]) << "pixel " << i;
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(denoised.image.pixels[i][c])) << "pixel " << i;
        changed += denoised.image.pixels[i] != plain.image.pixels[i] ? 1 : 0;
    }
    // At 4 samples nearly every pixel is noisy enough for its neighbours to move it.
    EXPECT_GT(changed, plain.image.pixels.size() / 2);
}

TEST_F(DenoiseCommand, MergeDenoisesTheMergedFrameAsOneRenderWould) {
    const ExrImage whole = render("whole.exr", "--spp 4");
    render("part0.exr", "--spp 2 --no-denoise");
    render("part1.exr", "--spp 2 --first-sample 2");  // a part's own beauty, denoised or not, is not read
    const test::RunResult r = test::runWovenCommand("merge '" + file("part0.exr") + "' '" + file("part1.exr") + "' -o '" +
                                                    file("merged.exr") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const ExrImage merged = readExr(file("merged.exr"));
    ASSERT_TRUE(merged.noisy.has_value());
    ASSERT_EQ(merged.image.pixels.size(), whole.image.pixels.size());
    for (size_t i = 0; i < whole.image.pixels.size(); ++i) {
        ASSERT_EQ(merged.image.pixels[i], whole.image.pixels[i]) << "pixel " << i;
        ASSERT_EQ(merged.noisy->pixels[i], whole.noisy->pixels[i]) << "pixel " << i;
    }
    const test::RunResult plain = test::runWovenCommand("merge --no-denoise '" + file("part0.exr") + "' '" + file("part1.exr") +
                                                        "' -o '" + file("plain.exr") + "'");
    ASSERT_EQ(plain.exitCode, 0) << plain.out;
    const ExrImage undenoised = readExr(file("plain.exr"));
    EXPECT_FALSE(undenoised.noisy.has_value());
    for (size_t i = 0; i < whole.image.pixels.size(); ++i) ASSERT_EQ(undenoised.image.pixels[i], whole.noisy->pixels[i]) << "pixel " << i;
}

TEST_F(DenoiseCommand, NoPassesKeepsTheBeautyAloneTheSameToTheBit) {
    // Each integrator named: auto's choice is timed, so two renders under load may differ in it.
    for (const std::string integrator : {"path", "bdpt"}) {
        const ExrImage plain = render(integrator + "_plain.exr", "--spp 4 --no-denoise --integrator " + integrator);
        // --no-passes alone: the denoiser, which the passes guide, goes with them.
        const ExrImage bare = render(integrator + "_bare.exr", "--spp 4 --no-passes --integrator " + integrator);
        ASSERT_FALSE(plain.passSums.empty()) << integrator;
        EXPECT_TRUE(bare.passSums.empty()) << integrator;
        EXPECT_FALSE(bare.noisy.has_value()) << integrator;
        // The first hits' records take no random numbers: the samples, and so the sums, are the same.
        ASSERT_EQ(bare.sampleSums.size(), plain.sampleSums.size()) << integrator;
        for (size_t i = 0; i < plain.sampleSums.size(); ++i)
            ASSERT_EQ(bare.sampleSums[i], plain.sampleSums[i]) << integrator << ", sum " << i;
        for (size_t i = 0; i < plain.image.pixels.size(); ++i)
            ASSERT_EQ(bare.image.pixels[i], plain.image.pixels[i]) << integrator << ", pixel " << i;
    }

    // Asked to denoise without the passes: an error that says which to drop, and no frame.
    const std::string out = file("both.exr");
    const test::RunResult r = test::runWovenCommand("render '" WOVEN_ASSETS_DIR "/default_scene.json' --width 48 --height 36 "
                                                    "--spp 4 --no-passes --denoise -o '" + out + "'");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("--no-passes"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--no-denoise"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace woven
