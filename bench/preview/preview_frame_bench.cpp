// Preview frame time (render + glFinish) of the default scene at 640x480 and 1280x720 through
// headless GL (llvmpipe here; the GPU through EGL where there is one), with the woven features,
// the far-field weave filter and the shadows compiled in or out; and the frame time while a
// light moves, which re-renders the shadow maps every frame. Also prints the number of lights
// the shader loops over, which the frame time is proportional to where the filter is on.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iostream>

#include "demo_scene.h"
#include "headless_gl.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
#include "scene_loader.h"

namespace woven {
namespace {

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
    for (auto _ : state) {
        renderer.render(scene, lights, camera, size, options);
        glFinish();
    }
}
BENCHMARK(previewFrame)
    ->Args({640, 480, 1, 1, 1})->Args({1280, 720, 1, 1, 1})
    ->Args({640, 480, 0, 1, 1})->Args({640, 480, 1, 0, 1})->Args({640, 480, 1, 1, 0})->Args({1280, 720, 1, 1, 0})
    ->Args({320, 240, 1, 1, 1})->Args({2560, 1440, 1, 1, 1})
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

}  // namespace
}  // namespace woven

BENCHMARK_MAIN();
