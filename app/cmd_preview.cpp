// `woven preview [SCENE]`: the interactive previewer, or with --headless one preview frame
// (or with --final the path-traced frame) written to a PNG.
#include <memory>
#include <stdexcept>

#include "commands.h"
#include "demo_scene.h"
#include "final_render.h"
#include "headless_gl.h"
#include "image_io.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
#include "preview_window.h"
#include "scene_loader.h"

namespace woven {

namespace {

struct PreviewCommandOptions {
    std::string scene;
    bool headless = false;
    bool final = false;
    std::string screenshot;
    int width = 960, height = 540;
    float exposure = 0.0f;
    bool noFilter = false;
    int spp = 16;
    int frames = 0;
    std::string windowScreenshot;
};

SceneDescription openScene(const std::string& path) { return path.empty() ? wavyClothScene() : loadScene(path); }

void runHeadless(const PreviewCommandOptions& o) {
    if (o.screenshot.empty()) throw std::invalid_argument("--headless needs --screenshot FILE.png");
    const SceneDescription scene = openScene(o.scene);
    const Camera camera = OrbitCamera::forScene(scene).camera();
    PngOptions png;
    png.exposure = o.exposure;
    if (o.final) {  // the Render button's path: core's RenderJob for the preview's camera
        RenderSettings settings;
        settings.width = o.width;
        settings.height = o.height;
        settings.spp = o.spp;
        settings.camera = camera;
        FinalRender render;
        render.start(scene, settings);
        render.wait();
        if (!render.error().empty()) throw std::runtime_error(render.error());
        writePng(o.screenshot, render.latest()->radiance, png);
        return;
    }
    auto gl = HeadlessGl::create();
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    PreviewOptions options;
    options.exposure = o.exposure;
    options.filterWeave = !o.noFilter;
    renderer.render(scene, PreviewLights::fromScene(scene), camera, {o.width, o.height}, options);
    writePng(o.screenshot, renderer.radiance(), png);
}

}  // namespace

void addPreviewCommand(CLI::App& app) {
    auto o = std::make_shared<PreviewCommandOptions>();
    CLI::App* cmd = app.add_subcommand("preview", "Tune a woven material live (OpenGL), or take a headless screenshot");
    cmd->add_option("scene", o->scene, "glTF or woven scene file (default: a procedural cloth)");
    cmd->add_flag("--headless", o->headless, "Render one frame without a window (EGL, else OSMesa)");
    cmd->add_flag("--final", o->final, "With --headless: the path-traced frame of the Render button");
    cmd->add_option("--screenshot", o->screenshot, "PNG to write");
    cmd->add_option("--width", o->width, "Image width in pixels")->check(CLI::Range(1, 16384));
    cmd->add_option("--height", o->height, "Image height in pixels")->check(CLI::Range(1, 16384));
    cmd->add_option("--exposure", o->exposure, "Exposure in stops");
    cmd->add_option("--spp", o->spp, "With --final: samples per pixel")->check(CLI::Range(1, 1 << 20));
    cmd->add_flag("--no-filter", o->noFilter, "Point-sample the weave even where it is finer than a pixel");
    cmd->add_option("--frames", o->frames, "Window: quit after N frames (0 = when closed)")->check(CLI::NonNegativeNumber);
    cmd->add_option("--window-screenshot", o->windowScreenshot, "Window: PNG of the last frame, panel included");
    cmd->callback([o] {
        if (o->headless) return runHeadless(*o);
        PreviewWindowOptions window;
        window.scene = o->scene;
        window.frames = o->frames;
        window.screenshot = o->windowScreenshot;
        window.width = o->width;
        window.height = o->height;
        window.spp = o->spp;
        runPreviewWindow(window);
    });
}

}  // namespace woven
