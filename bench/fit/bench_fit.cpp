// woven fit on a pair of 512 x 512 photos of the synthetic capture rig (tests/fit/capture_rig.h):
// the flash beside the lens and a second light, denim's 25 ends and 16 picks per cm as a 3/1
// twill. The second light is 3 cm to the side ("side"), or 15 cm behind the swatch ("backlit",
// the rig: yarns that pass t = 0.5 with g = 0.3, both photos at exposure 0.5, given).
// The goal is at most 4 minutes on 2 cores. Prints a table: renders, seconds a render,
// the stages reached, the thread counts' errors, the weave found, the worst channel of the
// colours and the transmission.
// Usage: bench_fit [seconds, default 180] [pixels, default 512] [side | backlit, default side]
#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "capture_rig.h"
#include "fabric_fit.h"
#include "weave_candidates.h"

int main(int argc, char** argv) {
    using namespace woven;
    const double seconds = argc > 1 ? std::atof(argv[1]) : 180.0;
    const int pixels = argc > 2 ? std::atoi(argv[2]) : 512;
    const std::string second = argc > 3 ? argv[3] : "side";
    if (second != "side" && second != "backlit") {
        std::fprintf(stderr, "bench_fit: the second light is side or backlit, not '%s'\n", second.c_str());
        return 2;
    }
    const auto dir = std::filesystem::temp_directory_path() / ("woven_bench_fit_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    test::RigPhoto photo;
    photo.truth.pattern = {1, 3, 1};
    photo.truth.repeat = {2500.0f, 1600.0f};  // per metre
    photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
    photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
    photo.size = pixels;
    if (second == "backlit") {
        photo.truth.transmission = 0.5f;
        photo.truth.transmission_gloss = 0.3f;
        photo.exposure = 0.5f;
    }
    std::vector<Shot> shots;
    shots.push_back(loadShot(test::writeCaptureShot(dir.string(), "flash", photo), "Swatch"));
    if (second == "backlit") {
        // As the round trips' pair (tests/fit/round_trip_test.cpp): 2 cm aside, so that the
        // glossy part's forward peak falls in the frame, 10 times the flash's intensity.
        photo.light = {0.02f, -0.15f, 0.0f};
        photo.lightIntensity = 0.8f;
    } else {
        photo.light.x = 0.03f;
    }
    photo.seed += 1;
    shots.push_back(loadShot(test::writeCaptureShot(dir.string(), second, photo), "Swatch"));

    FitOptions options;
    options.seconds = seconds;
    const std::atomic<bool> cancel{false};
    const auto start = std::chrono::steady_clock::now();
    // Where the time goes: one line each time the stage changes.
    std::string stage;
    const FitResult r = fitFabric(shots, options, cancel, [&](const FitProgress& p) {
        if (p.stage == stage) return;
        stage = p.stage;
        std::fprintf(stderr, "%7.1f s  %4d renders  %s\n", p.elapsed, p.evaluations, stage.c_str());
    });
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const WovenParams& f = r.params;
    std::fprintf(stderr, "fitted: weft %.3f %.3f %.3f, warp %.3f %.3f %.3f, ex %.1f, ey %.2f, widths %.3f %.3f, cy %.3f, rs %.3f, loss %.4g\n",
                 f.weft_color.r, f.weft_color.g, f.weft_color.b, f.warp_color.r, f.warp_color.g, f.warp_color.b, f.ex, f.ey,
                 f.yarn_width, f.warp_width, f.cy, f.rs, r.loss);
    // The exposure is given: the colours are compared as they are.
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max({worst, std::abs(r.params.weft_color[c] / photo.truth.weft_color[c] - 1.0),
                          std::abs(r.params.warp_color[c] / photo.truth.warp_color[c] - 1.0)});
    std::printf("| pixels | second light | budget s | took s | renders | s a render | stages done | ends error | picks error | "
                "weave | colours' worst channel | t, g |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::printf("| %d | %s | %.0f | %.1f | %d | %.3f | %s | %+.2f %% | %+.2f %% | %s | %.1f %% | %.3f, %.3f |\n", pixels,
                second.c_str(), seconds, took, r.evaluations, took / std::max(r.evaluations, 1),
                r.complete ? "all" : "not all", 100.0 * (r.params.repeat.x / photo.truth.repeat.x - 1.0),
                100.0 * (r.params.repeat.y / photo.truth.repeat.y - 1.0), describeWeave(r.params.pattern).c_str(),
                100.0 * worst, r.params.transmission, r.params.transmission_gloss);
    std::filesystem::remove_all(dir);
    return 0;
}
