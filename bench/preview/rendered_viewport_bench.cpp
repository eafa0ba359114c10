// The window's Rendered view (app/preview/rendered_viewport.h) on the default scene with 2
// threads, at 640x360 and 1280x720: the time from a slider change (a woven parameter, while 64
// passes are under way) to the first frame of the changed cloth, while the slider moves (the
// interactive resolution) and once it rests (full size); the time to a denoised frame of 16
// samples a pixel from a scene not yet built; passes per second; the denoiser's share of the
// view's time; the time to build the scene again after a material edit (on the BVH built); and
// the GLSL view's frame rate, alone and while the passes run beside it (as beside the Render
// button's frame, on the same cores): at full size, and as the window renders while the camera
// or a slider moves (InteractiveResolution). Printed tables, never a test: every figure depends
// on the machine and its load.
// Beside each wall time, the process's CPU time over its 2 threads: on a machine that others
// load, what the wall time would be with the 2 cores to itself (roughly: the threads are not
// busy all the time).
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "demo_scene.h"
#include "headless_gl.h"
#include "interactive_resolution.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
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

SceneDescription benchScene() {
    const std::string file = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    return std::filesystem::exists(file) ? loadScene(file) : wavyClothScene();
}

// The GLSL view's frames a second over kGlslSeconds of frames (rendered and finished), at
// `full` size or, `interacting`, at the size InteractiveResolution gives each frame as the
// window's while the camera or a slider moves; and the process's CPU milliseconds a frame.
constexpr double kGlslSeconds = 4.0;
struct GlslRate {
    double fps = 0.0, cpuMs = 0.0;
    float scale = 1.0f;  // of the last frame's side
};
GlslRate glslFrameRate(PreviewRenderer& renderer, const SceneDescription& scene, const Camera& camera, glm::ivec2 full,
                       bool interacting) {
    const PreviewLights lights = PreviewLights::fromScene(scene);
    InteractiveResolution resolution;
    const Timer timer;
    int frames = 0;
    for (Clock::time_point frame = timer.wall; secondsSince(timer.wall) < kGlslSeconds; ++frames) {
        const glm::ivec2 size = resolution.frameSize(full, interacting, secondsSince(timer.wall));
        renderer.render(scene, lights, camera, size, {});
        glFinish();
        resolution.frameTook(secondsSince(frame));
        frame = Clock::now();
    }
    return {frames / secondsSince(timer.wall), 1e3 * (cpuSeconds() - timer.cpu) / frames, resolution.scale()};
}

// The GLSL view alone, then beside the path tracer's passes (a still view of many samples,
// denoised as the window's), at full size and interacting; and the passes a second left to the
// path tracer meanwhile.
void benchGlslBeside(int width, int height) {
    const SceneDescription scene = benchScene();
    RenderSettings settings = viewportSettings(defaultRenderSettings(scene));
    settings.width = width;
    settings.height = height;
    settings.threads = kThreads;
    settings.spp = 100000;
    settings.camera = OrbitCamera::forScene(scene).camera();
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    glslFrameRate(renderer, scene, *settings.camera, {width, height}, false);  // compiles, warms
    const GlslRate fullAlone = glslFrameRate(renderer, scene, *settings.camera, {width, height}, false);
    const GlslRate movingAlone = glslFrameRate(renderer, scene, *settings.camera, {width, height}, true);
    RenderedViewport view;
    view.show(scene, settings, false, true);
    untilSamples(view, 1);
    const int passesBefore = view.progress().samples;
    const Clock::time_point start = Clock::now();
    const GlslRate fullBeside = glslFrameRate(renderer, scene, *settings.camera, {width, height}, false);
    const GlslRate movingBeside = glslFrameRate(renderer, scene, *settings.camera, {width, height}, true);
    const double passesPerSecond = (view.progress().samples - passesBefore) / secondsSince(start);
    view.stop();
    std::printf("| %dx%d | %.1f (%.0f) | %.1f | %.1f (%.0f) at %.2f | %.1f at %.2f | %.2f |\n", width, height, fullAlone.fps,
                fullAlone.cpuMs, fullBeside.fps, movingAlone.fps, movingAlone.cpuMs, movingAlone.scale, movingBeside.fps,
                movingBeside.scale, passesPerSecond);
}

void benchSize(int width, int height) {
    SceneDescription scene = benchScene();
    RenderSettings settings = viewportSettings(defaultRenderSettings(scene));
    settings.width = width;
    settings.height = height;
    settings.threads = kThreads;
    settings.camera = OrbitCamera::forScene(scene).camera();

    Clock::time_point start = Clock::now();
    RenderScene built(std::make_shared<const SceneDescription>(scene));
    const double buildSeconds = secondsSince(start);
    // A material edit: the materials and lights built again on the BVH.
    SceneDescription edited = scene;
    firstWoven(edited).ex += 5.0f;
    start = Clock::now();
    const RenderScene rebuilt(std::make_shared<const SceneDescription>(edited), std::move(built));
    const double rebuildSeconds = secondsSince(start);
    if (!rebuilt.tookGeometry()) throw std::runtime_error("a material edit built the BVH again");

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

    std::printf("| %dx%d | %.3f | %.4f | %.2f (%.2f) at %dx%d | %.2f (%.2f) | %.1f (%.1f) | %.2f (%.2f) | %.0f%% (%d denoised) |\n", width,
                height, buildSeconds, rebuildSeconds, movingWall, movingCpu, movingPass.width, movingPass.height, restingWall, restingCpu,
                denoised16Wall, denoised16Cpu, plainRun.samples / plainRun.seconds, plainRun.samples / plainCpu,
                100.0 * denoisedRun.denoiseSeconds / denoisedRun.seconds, denoisedRun.denoisings);
}

}  // namespace
}  // namespace woven

int main() {
    std::printf("Rendered view, default scene, %d threads, path tracer: wall seconds (CPU seconds / %d)\n\n", woven::kThreads,
                woven::kThreads);
    std::printf("| size | scene build s | material edit: build s | slider moving: first frame s | slider resting: first frame s | denoised 16 spp s | passes/s | denoiser's share |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    woven::benchSize(640, 360);
    woven::benchSize(1280, 720);
    const auto gl = woven::HeadlessGl::create();
    std::printf("\nThe GLSL view (%s), frames a second, alone (CPU ms a frame) and beside the passes\n"
                "(whose threads' CPU the process's would count too); moving: at the InteractiveResolution scale of the\n"
                "side it settled to:\n\n", gl->description().c_str());
    std::printf("| size | full size alone | full size beside | moving alone | moving beside | passes/s beside |\n");
    std::printf("|---|---|---|---|---|---|\n");
    woven::benchGlslBeside(640, 360);
    woven::benchGlslBeside(1280, 720);
    // What the window pays each frame in the Rendered view to see whether the scene changed.
    const woven::SceneDescription scene = woven::benchScene();
    constexpr int kHashes = 50;
    const woven::Clock::time_point start = woven::Clock::now();
    for (int i = 0; i < kHashes; ++i) woven::sceneHash(scene, woven::Camera{});
    std::printf("\nthe scene's hash, each frame: %.2f ms\n", 1e3 * woven::secondsSince(start) / kHashes);
}
