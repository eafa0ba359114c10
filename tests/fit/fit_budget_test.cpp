// The fit's time budget holds without reading the clock's precision: a render whose deadline has
// passed stops after its first pass and comes back empty, and a fit whose budget is spent before
// its first render (or that Ctrl-C cancelled) returns at once with what stage 1 measured.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>

#include "capture_rig.h"
#include "fabric_fit.h"
#include "shot.h"
#include "shot_render.h"
#include "temp_dir_test.h"

namespace woven::test {
namespace {

class FitBudget : public TempDirTest {
protected:
    // The rig's 3/1 twill, 800 threads per metre each way: 32 threads across 128 pixels.
    Shot shot() {
        RigPhoto photo;
        photo.truth.pattern = {1, 3, 1};
        photo.truth.repeat = {800.0f, 800.0f};
        photo.spp = 4;
        return loadShot(writeCaptureShot(dir_.string(), "shot", photo), "Swatch");
    }
};

TEST_F(FitBudget, RenderPastItsDeadlineComesBackEmpty) {
    const Shot s = shot();
    const std::atomic<bool> cancel{false};
    FitRenderSettings settings;
    settings.spp = 64;
    const WovenParams params;
    EXPECT_EQ(renderShot(s, params, settings, cancel).pixels.size(), size_t(128 * 128));  // no deadline: whole
    settings.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    EXPECT_TRUE(renderShot(s, params, settings, cancel).pixels.empty());
    EXPECT_TRUE(renderShotLambertian(s, settings, cancel).pixels.empty());
}

// Every render of these fits is cut short: the budget ends as the fit starts, or Ctrl-C came
// first. What stands is the shot's material with stage 1's thread counts, said to be unfinished.
TEST_F(FitBudget, FitWithNoTimeLeftReturnsStageOnesThreadCounts) {
    const std::vector<Shot> shots{shot()};
    for (const bool cancelled : {false, true}) {
        FitOptions options;
        options.seconds = cancelled ? 600.0 : 0.0;
        const std::atomic<bool> cancel{cancelled};
        const FitResult r = fitFabric(shots, options, cancel);
        EXPECT_FALSE(r.complete) << cancelled;
        EXPECT_EQ(r.evaluations, 0) << cancelled;
        EXPECT_TRUE(r.history.empty()) << cancelled;
        EXPECT_NEAR(r.params.repeat.x, 800.0f, 0.03f * 800.0f) << cancelled;
        EXPECT_NEAR(r.params.repeat.y, 800.0f, 0.03f * 800.0f) << cancelled;
        if (!cancelled) {
            ASSERT_FALSE(r.warnings.empty());
            EXPECT_NE(r.warnings.back().find("no render finished within the budget"), std::string::npos) << r.warnings.back();
        }
    }
}

}  // namespace
}  // namespace woven::test
