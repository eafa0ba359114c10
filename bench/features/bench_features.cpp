// What each woven feature costs a render: samples per second of the path tracer on a scene with
// every woven feature off, then with bump, noise, crimp and gaps switched on one at a time.
// A feature a scene does not use must cost it nothing: the "off" rows are the check.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>

#include "render_job.h"
#include "scene_loader.h"

using namespace woven;

namespace {

double samplesPerSecond(const SceneDescription& scene, int width, int height, int spp, int repeats) {
    auto shared = std::make_shared<const SceneDescription>(scene);
    double best = 0.0;
    for (int r = 0; r < repeats; ++r) {
        RenderSettings s;
        s.width = width;
        s.height = height;
        s.spp = spp;
        s.integrator = "path";
        RenderJob job(shared, s);
        std::atomic<bool> cancel{false};
        const auto start = std::chrono::steady_clock::now();
        job.run(cancel);
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::max(best, double(width) * height * spp / t);  // best of: least disturbed run
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string path = argc > 1 ? argv[1] : WOVEN_DEFAULT_SCENE;
    SceneDescription scene;
    try {
        scene = loadScene(path);
    } catch (const std::exception& e) {
        std::cerr << "bench_features: " << e.what() << "\n";
        return 1;
    }
    // Every woven feature off: flat yarns, full widths (no gaps), no noise, no crimp.
    auto forEachWoven = [&](SceneDescription& s, const std::function<void(WovenParams&)>& f) {
        for (Material& m : s.materials)
            if (m.woven) f(*m.woven);
    };
    SceneDescription base = scene;
    forEachWoven(base, [](WovenParams& p) {
        p.cy = 0.0f; p.noise = 0.0f; p.crimp = 0.0f; p.yarn_width = 1.0f; p.warp_width = 1.0f; p.backing = 0;
    });
    struct Variant { const char* name; std::function<void(WovenParams&)> change; };
    const Variant variants[] = {
        {"all off", [](WovenParams&) {}},
        {"bump (cy = 0.75)", [](WovenParams& p) { p.cy = 0.75f; }},
        {"noise (0.3)", [](WovenParams& p) { p.noise = 0.3f; }},
        {"crimp (0.5)", [](WovenParams& p) { p.crimp = 0.5f; }},
        {"gaps (widths 0.8, see-through)", [](WovenParams& p) { p.yarn_width = 0.8f; p.warp_width = 0.8f; }},
        {"all on", [](WovenParams& p) { p.cy = 0.75f; p.noise = 0.3f; p.crimp = 0.5f; p.yarn_width = 0.8f; p.warp_width = 0.8f; }},
    };
    const int width = 320, height = 240, spp = 4, repeats = 3;
    std::printf("scene %s, path tracer, %dx%d, %d spp, best of %d\n\n", path.c_str(), width, height, spp, repeats);
    std::printf("| woven features | samples/s | vs all off |\n|---|---:|---:|\n");
    double baseline = 0.0;
    for (const Variant& v : variants) {
        SceneDescription s = base;
        forEachWoven(s, v.change);
        const double rate = samplesPerSecond(s, width, height, spp, repeats);
        if (baseline == 0.0) baseline = rate;
        std::printf("| %s | %.0f | %.3f |\n", v.name, rate, rate / baseline);
    }
    return 0;
}
