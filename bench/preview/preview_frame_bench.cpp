// Preview frame time (render + glFinish) of the default scene at 640x480 and 1280x720 through
// headless GL (llvmpipe here; the GPU through EGL where there is one), with the woven features,
// the far-field weave filter and the shadows compiled in or out; and the frame time while a
// light moves, which re-renders the shadow maps every frame. Also prints the number of lights
// the shader loops over, which the frame time is proportional to where the filter is on. And the
// window's frames at 1280x720 as the user sees them (render, display into the window-sized
// target, glFinish): at fixed scales, and sized by InteractiveResolution while the camera moves.
// And what coloured shadows cost: assets/coloured_shadow.json with its sheets letting light
// through against the same sheets opaque (as every scene rendered before them), the lights still
// and moving.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "demo_scene.h"
#include "headless_gl.h"
#include "interactive_resolution.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
#include "scene_loader.h"

namespace woven {
namespace {

// CPU time of the process, llvmpipe's threads included: it bounds a frame's wall time on an idle
// machine from above, whatever else shares a loaded one (cpu_ms in the table).
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

SceneDescription benchScene(bool features) {
    const std::string file = std::string(WOVEN_ASSETS_DIR) + "/default_scene.json";
    SceneDescription scene = std::filesystem::exists(file) ? loadScene(file) : wavyClothScene();
    for (Material& m : scene.materials)
        if (m.woven && !features) {
            m.woven->noise = 0.0f;
            m.woven->crimp = 0.0f;
            m.woven->yarn_width = m.woven->warp_width = 1.0f;
        }
    return scene;
}

void previewFrame(benchmark::State& state) {
    static auto gl = HeadlessGl::create();
    static bool printed = (std::cout << gl->description() << "\n", true);
    (void)printed;
    const SceneDescription scene = benchScene(state.range(2) != 0);
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    const PreviewLights lights = PreviewLights::fromScene(scene);
    static bool printedLights = (std::cout << lights.lights.size() << " preview lights\n", true);
    (void)printedLights;
    PreviewOptions options;
    options.filterWeave = state.range(3) != 0;
    options.shadows = state.range(4) != 0;
    const Camera camera = OrbitCamera::forScene(scene).camera();
    const glm::ivec2 size(int(state.range(0)), int(state.range(1)));
    renderer.render(scene, lights, camera, size, options);  // compiles the programs
    glFinish();
    const double cpuStart = cpuSeconds();
    for (auto _ : state) {
        renderer.render(scene, lights, camera, size, options);
        glFinish();
    }
    state.counters["cpu_ms"] = 1e3 * (cpuSeconds() - cpuStart) / double(state.iterations());
}
BENCHMARK(previewFrame)
    ->Args({640, 480, 1, 1, 1})->Args({1280, 720, 1, 1, 1})
    ->Args({640, 480, 0, 1, 1})->Args({640, 480, 1, 0, 1})->Args({640, 480, 1, 1, 0})->Args({1280, 720, 1, 1, 0})
    ->Args({320, 240, 1, 1, 1})->Args({320, 180, 1, 1, 1})->Args({2560, 1440, 1, 1, 1})
    ->ArgNames({"w", "h", "features", "filter", "shadows"})->Unit(benchmark::kMillisecond)->UseRealTime();

// Dragging a light: every frame re-renders the shadow maps (a cube per light sample).
void previewFrameLightMoving(benchmark::State& state) {
    static auto gl = HeadlessGl::create();
    const SceneDescription scene = benchScene(true);
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    PreviewLights lights = PreviewLights::fromScene(scene);
    const Camera camera = OrbitCamera::forScene(scene).camera();
    const glm::ivec2 size(int(state.range(0)), int(state.range(1)));
    renderer.render(scene, lights, camera, size, {});
    glFinish();
    float offset = 0.0f;
    for (auto _ : state) {
        offset = offset == 0.0f ? 1e-3f : 0.0f;
        for (PreviewLight& l : lights.lights) l.position.x += offset == 0.0f ? -1e-3f : 1e-3f;
        renderer.render(scene, lights, camera, size, {});
        glFinish();
    }
}
BENCHMARK(previewFrameLightMoving)->Args({640, 480})->ArgNames({"w", "h"})->Unit(benchmark::kMillisecond)->UseRealTime();

// The window's frame at 1280x720 as PreviewWindow::run() draws it: rendered (orbiting the camera
// a little every frame) and shown at the window's size through the display transform. `scale`
// in per cent of the window; 0: sized by InteractiveResolution while interacting, from the
// frames' measured wall times, after 30 frames to settle.
void previewWindowFrame(benchmark::State& state) {
    static auto gl = HeadlessGl::create();
    const SceneDescription scene = benchScene(true);
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    const PreviewLights lights = PreviewLights::fromScene(scene);
    OrbitCamera orbit = OrbitCamera::forScene(scene);
    const glm::ivec2 window(1280, 720);
    const int scale = int(state.range(0));
    GLuint target = 0, framebuffer = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, window.x, window.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);

    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    InteractiveResolution resolution;
    const auto frame = [&] {
        const Clock::time_point begin = Clock::now();
        orbit.orbit(0.01f, 0.0f);
        Camera camera = orbit.camera();
        camera.aspect = float(window.x) / float(window.y);
        const double now = std::chrono::duration<double>(begin - start).count();
        const glm::ivec2 size = scale > 0 ? glm::ivec2(glm::vec2(window) * (float(scale) / 100.0f))
                                          : resolution.frameSize(window, true, now);
        renderer.render(scene, lights, camera, size, {});
        renderer.display(framebuffer, {0, 0}, window, {});
        glFinish();
        resolution.frameTook(std::chrono::duration<double>(Clock::now() - begin).count());
    };
    for (int i = 0; i < 30; ++i) frame();
    const double cpuStart = cpuSeconds();
    for (auto _ : state) frame();
    state.counters["scale"] = scale > 0 ? float(scale) / 100.0f : resolution.scale();
    state.counters["cpu_ms"] = 1e3 * (cpuSeconds() - cpuStart) / double(state.iterations());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
}
BENCHMARK(previewWindowFrame)
    ->Arg(0)->Arg(100)->Arg(50)->Arg(25)->Arg(15)->Arg(12)
    ->ArgNames({"scale"})->Unit(benchmark::kMillisecond)->UseRealTime();

// assets/coloured_shadow.json at 640x480: `transmits` 0 makes its voile's yarns and its leaf pass
// nothing (opaque casters, no transmittance pass, no coloured lookups); `moving` 1 moves the light
// every frame, which re-renders the shadow maps (and the transmittance pass) each time.
void previewFrameColouredShadow(benchmark::State& state) {
    static auto gl = HeadlessGl::create();
    SceneDescription scene = loadScene(std::string(WOVEN_ASSETS_DIR) + "/coloured_shadow.json");
    if (state.range(0) == 0)
        for (Material& m : scene.materials) {
            if (m.woven) m.woven->transmission = 0.0f;
            m.diffuseTransmission.factor = 0.0f;
        }
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    PreviewLights lights = PreviewLights::fromScene(scene);
    const Camera camera = OrbitCamera::forScene(scene).camera();
    const glm::ivec2 size(640, 480);
    renderer.render(scene, lights, camera, size, {});  // compiles the programs
    glFinish();
    const bool moving = state.range(1) != 0;
    float offset = 0.0f;
    const double cpuStart = cpuSeconds();
    for (auto _ : state) {
        if (moving) {
            offset = offset == 0.0f ? 1e-3f : 0.0f;
            for (PreviewLight& l : lights.lights) l.position.x += offset == 0.0f ? -1e-3f : 1e-3f;
        }
        renderer.render(scene, lights, camera, size, {});
        glFinish();
    }
    state.counters["cpu_ms"] = 1e3 * (cpuSeconds() - cpuStart) / double(state.iterations());
}
BENCHMARK(previewFrameColouredShadow)
    ->Args({0, 0})->Args({1, 0})->Args({0, 1})->Args({1, 1})
    ->ArgNames({"transmits", "moving"})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace woven

BENCHMARK_MAIN();
