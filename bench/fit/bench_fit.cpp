// woven fit on a pair of 512 x 512 photos of the synthetic capture rig (tests/fit/capture_rig.h):
// the flash beside the lens and a light 3 cm to the side, denim's 25 ends and 16 picks per cm as a
// 3/1 twill. The goal is at most 4 minutes on 2 cores. Prints a table: renders, seconds
// a render, the stages reached, the thread counts' errors and the weave found.
// Usage: bench_fit [seconds, default 180] [pixels, default 512]
#include <atomic>
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
    const auto dir = std::filesystem::temp_directory_path() / ("woven_bench_fit_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    test::RigPhoto photo;
    photo.truth.pattern = {1, 3, 1};
    photo.truth.repeat = {2500.0f, 1600.0f};  // per metre
    photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
    photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
    photo.size = pixels;
    std::vector<Shot> shots;
    shots.push_back(loadShot(test::writeCaptureShot(dir.string(), "flash", photo), "Swatch"));
    photo.light.x = 0.03f;
    photo.seed += 1;
    shots.push_back(loadShot(test::writeCaptureShot(dir.string(), "side", photo), "Swatch"));

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
    std::printf("| pixels | shots | budget s | took s | renders | s a render (both shots) | stages done | ends error | picks error | weave |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    std::printf("| %d | %zu | %.0f | %.1f | %d | %.3f | %s | %+.2f %% | %+.2f %% | %s |\n", pixels, shots.size(), seconds,
                took, r.evaluations, took / std::max(r.evaluations, 1), r.complete ? "all" : "not all",
                100.0 * (r.params.repeat.x / photo.truth.repeat.x - 1.0),
                100.0 * (r.params.repeat.y / photo.truth.repeat.y - 1.0), describeWeave(r.params.pattern).c_str());
    std::filesystem::remove_all(dir);
    return 0;
}
