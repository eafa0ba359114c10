// What the render passes cost a final frame (issue 24: every frame file has them): the film's
// exact sums per pass, with the passes and without (the radiance's three sums alone, as the film
// added them before), against a pass of the default scene, and the frame file's write, with the
// passes and exact sums and with the beauty alone. Prints a table; no timing is asserted.
//   bench_passes [WIDTH HEIGHT SPP]   (default 320 240 16, the path tracer, no noise threshold)
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "film.h"
#include "frame_io.h"
#include "render_job.h"
#include "scene_loader.h"

using namespace woven;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 3 ? std::atoi(argv[1]) : 320, height = argc > 3 ? std::atoi(argv[2]) : 240,
              spp = argc > 3 ? std::atoi(argv[3]) : 16;
    auto scene = std::make_shared<const SceneDescription>(loadScene(WOVEN_DEFAULT_SCENE));
    RenderSettings s = defaultRenderSettings(*scene);
    s.width = width;
    s.height = height;
    s.spp = spp;
    s.integrator = "path";
    s.noiseThreshold = 0.0;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    Clock::time_point start = Clock::now();
    job.run(cancel);
    const double renderPerPass = secondsSince(start) / spp;
    const FilmImage film = job.snapshot();

    // A pass like the render's: its estimates and first hits, no splats.
    PassImage pass;
    pass.width = width;
    pass.height = height;
    pass.radiance = film.radiance.pixels;
    const RenderPasses passes = film.passes();
    for (size_t i = 0; i < pass.radiance.size(); ++i)
        pass.firstHits.push_back({passes.albedo.pixels[i], passes.normal.pixels[i], passes.depth[i], passes.direct.pixels[i]});
    pass.tileSplats.assign(1, {});
    Film bench(width, height);
    start = Clock::now();
    for (int k = 0; k < spp; ++k) bench.addPass(pass);
    const double filmPerPass = secondsSince(start) / spp;
    std::vector<ExactSum> radianceOnly(3 * pass.radiance.size());
    start = Clock::now();
    for (int k = 0; k < spp; ++k)
        for (size_t i = 0; i < pass.radiance.size(); ++i)
            for (int c = 0; c < 3; ++c) radianceOnly[3 * i + size_t(c)].add(pass.radiance[i][c]);
    const double radiancePerPass = secondsSince(start) / spp;

    const std::string full = std::filesystem::temp_directory_path() / "bench_passes_full.exr",
                      beauty = std::filesystem::temp_directory_path() / "bench_passes_beauty.exr";
    start = Clock::now();
    writeExr(full, film.exr(), ExrPrecision::Float);
    const double writeFull = secondsSince(start);
    start = Clock::now();
    writeExr(beauty, ExrImage{film.radiance, film.sampleCount}, ExrPrecision::Float);
    const double writeBeauty = secondsSince(start);
    const double render = renderPerPass * spp;

    std::printf("default scene, %dx%d, %d spp, path tracer: %.3f s a pass, %.2f s in all\n\n", width, height, spp,
                renderPerPass, render);
    std::printf("| what | seconds | share of the render |\n|---|---|---|\n");
    std::printf("| film, radiance sums alone, a pass | %.4f | %.2f %% |\n", radiancePerPass, 100.0 * radiancePerPass / renderPerPass);
    std::printf("| film with the passes' sums, a pass | %.4f | %.2f %% |\n", filmPerPass, 100.0 * filmPerPass / renderPerPass);
    std::printf("| frame file, beauty and count (%.1f MB) | %.3f | %.2f %% |\n", std::filesystem::file_size(beauty) / 1e6,
                writeBeauty, 100.0 * writeBeauty / render);
    std::printf("| frame file with passes and exact sums (%.1f MB) | %.3f | %.2f %% |\n", std::filesystem::file_size(full) / 1e6,
                writeFull, 100.0 * writeFull / render);
    std::filesystem::remove(full);
    std::filesystem::remove(beauty);
}
