// The denoiser's cost against the render's: renders a scene (the default scene unless one is
// given) with its default settings at 1280x720, then denoises the frame a few times, and prints
// both wall-clock times and their ratio. The budget: denoising takes at most 10 % of the
// render at the default settings.
//
//   bench_denoise [SCENE] [--width 1280] [--height 720] [--repeats 3] [--threads 0]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "frame_denoise.h"
#include "render_job.h"
#include "scene_loader.h"

using namespace woven;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    std::string scenePath = WOVEN_DEFAULT_SCENE;
    int width = 1280, height = 720, repeats = 3, threads = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "bench_denoise: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return std::atoi(argv[++i]);
        };
        if (a == "--width") width = value();
        else if (a == "--height") height = value();
        else if (a == "--repeats") repeats = std::max(1, value());
        else if (a == "--threads") threads = value();
        else if (!a.empty() && a[0] != '-') scenePath = a;
        else {
            std::fprintf(stderr, "bench_denoise: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    const auto scene = std::make_shared<const SceneDescription>(loadScene(scenePath));
    RenderSettings s = defaultRenderSettings(*scene);
    s.width = width;
    s.height = height;
    s.threads = threads;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    const auto renderStart = std::chrono::steady_clock::now();
    job.run(cancel);
    const double render = secondsSince(renderStart);
    FilmImage film = job.snapshot();
    std::printf("| frame | spp | integrator | denoiser | render (s) | denoise (s, best of %d) | denoise / render |\n"
                "|---|---:|---|---|---:|---:|---:|\n",
                repeats);
    // The default, and the filters alone: what the regression on the direct light adds (a scene
    // without the pass pays only the second).
    DenoiseSettings filtersOnly;
    filtersOnly.regression = false;
    for (const auto& [name, settings] : {std::pair{"default", DenoiseSettings{}}, std::pair{"filters alone", filtersOnly}}) {
        double best = 1e30;
        for (int r = 0; r < repeats; ++r) {
            const auto start = std::chrono::steady_clock::now();
            denoiseFilm(film, settings);  // the passes' means included: what a render pays
            best = std::min(best, secondsSince(start));
        }
        std::printf("| %s %dx%d | %d | %s | %s | %.2f | %.3f | %.1f %% |\n",
                    scenePath.substr(scenePath.find_last_of('/') + 1).c_str(), width, height, s.spp,
                    job.integratorName().c_str(), name, render, best, 100.0 * best / render);
    }
    return 0;
}
