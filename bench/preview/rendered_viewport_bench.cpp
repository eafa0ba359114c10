// The window's Rendered view (app/preview/rendered_viewport.h) on the default scene with 2
// threads, at 640x360 and 1280x720: the time from a slider change (a woven parameter, while 64
// passes are under way) to the first frame of the changed cloth, while the slider moves (the
// interactive resolution) and once it rests (full size); the time to a denoised frame of 16
// samples a pixel from a scene not yet built; passes per second; and the denoiser's share of the
// view's time. A printed table, never a test: every figure depends on the machine and its load.
// Beside each wall time, the process's CPU time over its 2 threads: on a machine that others
// load, what the wall time would be with the 2 cores to itself (roughly: the threads are not
// busy all the time).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "demo_scene.h"
#include "orbit_camera.h"
#include "render_scene.h"
#include "rendered_viewport.h"
#include "scene_hash.h"
#include "scene_loader.h"

namespace woven {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

constexpr int kThreads = 2;

double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Wall seconds since a start, and CPU seconds over the threads.
struct Timer {
    Clock::time_point wall = Clock::now();
    double cpu = cpuSeconds();
    double perThreadCpu() const { return (cpuSeconds() - cpu) / kThreads; }
};

// Waits until the view shows a pass of a restart after `restarts`.
void untilFirstPass(const RenderedViewport& view, uint64_t restarts) {
    for (;;) {
        const ViewportProgress p = view.progress();
        if (p.restarts > restarts && p.samples >= 1) return;
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
}

// Waits until `view` has `samples` passes in the current restart.
void untilSamples(const RenderedViewport& view, int samples) {
    while (view.progress().samples < samples) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

WovenParams& firstWoven(SceneDescription& scene) {
    for (Material& m : scene.materials)
        if (m.woven) return *m.woven;
    throw std::runtime_error("the bench scene has no woven material");
}

void benchSize(int width, int height) {
    const std::string file = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    SceneDescription scene = std::filesystem::exists(file) ? loadScene(file) : wavyClothScene();
    RenderSettings settings = viewportSettings(defaultRenderSettings(scene));
    settings.width = width;
    settings.height = height;
    settings.threads = kThreads;
    settings.camera = OrbitCamera::forScene(scene).camera();

    Clock::time_point start = Clock::now();
    RenderScene built(std::make_shared<const SceneDescription>(scene));
    const double buildSeconds = secondsSince(start);

    RenderedViewport view;
    // A denoised frame of 16 samples a pixel, the scene built first.
    settings.spp = 16;
    Timer denoised16;
    view.show(scene, settings, false, true);
    view.waitUntilIdle();
    const double denoised16Wall = secondsSince(denoised16.wall), denoised16Cpu = denoised16.perThreadCpu();
    const ViewportProgress denoisedRun = view.progress();
    // The same undenoised (the scene built already): passes per second.
    Timer plain;
    view.show(scene, settings, false, false);
    view.waitUntilIdle();
    const double plainCpu = plain.perThreadCpu();
    const ViewportProgress plainRun = view.progress();

    // A slider change while passes are under way, the slider moving, then resting.
    settings.spp = 64;
    view.show(scene, settings, false, true);
    untilSamples(view, 2);
    firstWoven(scene).ex += 5.0f;
    uint64_t restarts = view.progress().restarts;
    Timer moving;
    view.show(scene, settings, true, true);
    untilFirstPass(view, restarts);
    const double movingWall = secondsSince(moving.wall), movingCpu = moving.perThreadCpu();
    const ViewportProgress movingPass = view.progress();
    untilSamples(view, 2);
    firstWoven(scene).ex += 5.0f;
    restarts = view.progress().restarts;
    Timer resting;
    view.show(scene, settings, false, true);
    untilFirstPass(view, restarts);
    const double restingWall = secondsSince(resting.wall), restingCpu = resting.perThreadCpu();
    view.stop();

    std::printf("| %dx%d | %.3f | %.2f (%.2f) at %dx%d | %.2f (%.2f) | %.1f (%.1f) | %.2f (%.2f) | %.0f%% (%d denoised) |\n", width,
                height, buildSeconds, movingWall, movingCpu, movingPass.width, movingPass.height, restingWall, restingCpu,
                denoised16Wall, denoised16Cpu, plainRun.samples / plainRun.seconds, plainRun.samples / plainCpu,
                100.0 * denoisedRun.denoiseSeconds / denoisedRun.seconds, denoisedRun.denoisings);
}

}  // namespace
}  // namespace woven

int main() {
    std::printf("Rendered view, default scene, %d threads, path tracer: wall seconds (CPU seconds / %d)\n\n", woven::kThreads,
                woven::kThreads);
    std::printf("| size | scene build s | slider moving: first frame s | slider resting: first frame s | denoised 16 spp s | passes/s | denoiser's share |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    woven::benchSize(640, 360);
    woven::benchSize(1280, 720);
    // What the window pays each frame in the Rendered view to see whether the scene changed.
    const woven::SceneDescription scene = woven::loadScene(std::string(WOVEN_ASSETS_DIR) + "/default_scene.json");
    constexpr int kHashes = 50;
    const woven::Clock::time_point start = woven::Clock::now();
    for (int i = 0; i < kHashes; ++i) woven::sceneHash(scene, woven::Camera{});
    std::printf("\nthe scene's hash, each frame: %.2f ms\n", 1e3 * woven::secondsSince(start) / kHashes);
}
