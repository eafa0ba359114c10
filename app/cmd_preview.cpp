// `woven preview [SCENE]`: the interactive previewer, or with --headless one preview frame
// (or with --final the Render button's frame) written to a PNG or EXR.
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <stdexcept>

#include "choice_check.h"
#include "commands.h"
#include "number_checks.h"
#include "demo_scene.h"
#include "final_render.h"
#include "frame_options.h"
#include "headless_gl.h"
#include "frame_io.h"
#include "file_reading.h"
#include "image_io.h"
#include "output_path.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
#include "preview_window.h"
#include "rendered_viewport.h"
#include "scene_loader.h"

namespace woven {

namespace {

struct PreviewCommandOptions {
    std::string scene;
    bool headless = false;
    bool final = false;
    std::string viewport = "glsl";  // --viewport: the view the window opens with, or the headless frame's
    int passes = 0;                 // --passes: the rendered viewport's headless frame; 0: --spp's
    std::string screenshot;
    FrameOptions frame;  // --width/--height: also the window's and the screenshot's size
    bool noShadows = false;
    int frames = 0;
    std::string windowScreenshot;
    std::string wif;
    std::string widgetMap;
};

SceneDescription openScene(const PreviewCommandOptions& o) {
    SceneDescription scene = o.scene.empty() ? wavyClothScene() : loadScene(o.scene, o.frame.load);
    applySceneOptions(scene, o.frame);
    return scene;
}

// The window's options mean nothing to a headless frame, and the headless ones nothing to the
// window: each is refused where it would be dropped.
void checkModeOptions(const PreviewCommandOptions& o) {
    const std::vector<std::pair<bool, const char*>> windowOnly = {{o.frames != 0, "--frames"},
                                                       {!o.windowScreenshot.empty(), "--window-screenshot"},
                                                       {!o.wif.empty(), "--wif"},
                                                       {!o.widgetMap.empty(), "--widget-map"}};
    const std::vector<std::pair<bool, const char*>> headlessOnly = {
        {!o.screenshot.empty(), "--screenshot"}, {o.final, "--final"}, {o.passes != 0, "--passes"}};
    for (const auto& [given, name] : o.headless ? windowOnly : headlessOnly)
        if (given)
            throw std::invalid_argument(std::string(name) + " is for " +
                                        (o.headless ? "the previewer's window: --headless has none (its image is --screenshot)"
                                                    : "--headless (the window's image is --window-screenshot)"));
}

void runHeadless(const PreviewCommandOptions& o) {
    if (o.screenshot.empty()) throw std::invalid_argument("--headless needs --screenshot FILE.png (or .exr)");
    if (o.final && o.viewport == "rendered")
        throw std::invalid_argument("--final is the Render button's frame, --viewport rendered the view's: give one");
    if (o.passes != 0 && o.viewport != "rendered")
        throw std::invalid_argument("--passes counts the rendered view's passes: give --viewport rendered with it");
    checkFrameFileName(o.screenshot);
    const SceneDescription scene = openScene(o);
    checkOutput(o.screenshot);  // again, now that the scene's files are read: none may be replaced
    const Camera camera = OrbitCamera::forScene(scene).camera();
    if (o.final) {  // the Render button's path: core's RenderJob for the preview's camera
        RenderSettings settings = frameSettings(scene, o.frame);
        settings.camera = camera;
        FinalRender render;
        render.start(scene, settings, o.frame.denoise);
        render.wait();
        if (!render.error().empty()) throw std::runtime_error(render.error());
        const FilmImage film = *render.latest();
        writeFrame(o.screenshot, film.exr(), o.frame.display);
        return;
    }
    if (o.viewport == "rendered") {  // the view's Rendered mode, left to --passes passes
        RenderSettings settings = viewportSettings(frameSettings(scene, o.frame));
        settings.camera = camera;
        if (o.passes > 0) settings.spp = o.passes;
        RenderedViewport view;
        view.show(scene, settings, false, o.frame.denoise);
        view.waitUntilIdle();
        if (!view.error().empty()) throw std::runtime_error(view.error());
        const std::optional<FilmImage> frame = view.frame();
        if (!frame) throw std::runtime_error("the rendered view ended without a frame");
        writeFrame(o.screenshot, frame->exr(), o.frame.display);
        return;
    }
    auto gl = HeadlessGl::create();
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    PreviewOptions options;
    options.filterWeave = !o.frame.noFilter;
    options.shadows = !o.noShadows;
    // The size the Render button's frame would have, so both frame the scene alike.
    const RenderSettings settings = frameSettings(scene, o.frame);
    const glm::ivec2 size(settings.width, settings.height);
    renderer.renderRefined(scene, PreviewLights::fromScene(scene), camera, size, options);  // as a resting window shows it
    writeFrame(o.screenshot, {renderer.radiance(), {}}, o.frame.display);
}

}  // namespace

void addPreviewCommand(CLI::App& app) {
    auto o = std::make_shared<PreviewCommandOptions>();
    CLI::App* cmd = app.add_subcommand("preview", "Tune a woven material live (OpenGL), or take a headless screenshot");
    cmd->add_option("scene", o->scene, "glTF or woven scene file (default: a procedural cloth)");
    cmd->add_flag("--headless", o->headless, "Render one frame without a window (EGL, else OSMesa)");
    cmd->add_flag("--final", o->final, "With --headless: the path-traced frame of the Render button");
    cmd->add_option("--viewport", o->viewport,
                    "glsl: the view drawn by OpenGL (default); rendered: by the path tracer, progressively (key R in the "
                    "window; with --headless, the frame after --passes passes)")
        ->check(oneOf({"glsl", "rendered"}));
    cmd->add_option("--passes", o->passes,
                    "With --headless --viewport rendered: the passes (samples a pixel) the frame takes (default: --spp's)")
        ->transform(wholeNumber(1, 1 << 24));
    cmd->add_option("--screenshot", o->screenshot, "With --headless: the image to write (.png, or .exr for linear radiance)");
    addFrameOptions(*cmd, o->frame);
    cmd->add_flag("--no-shadows", o->noShadows, "Light every surface as if nothing stood in the way");
    cmd->add_flag("--no-filter", o->frame.noFilter,
                  "Point-sample the weave in the preview even where it is finer than a pixel (the Render button "
                  "filters only with --filter)");
    cmd->add_option("--frames", o->frames, "Window: quit after N frames (0 = when closed, or on SIGINT or SIGTERM)")->transform(wholeNumber(0));
    cmd->add_option("--window-screenshot", o->windowScreenshot, "Window: PNG of the last frame, panel included");
    cmd->add_option("--widget-map", o->widgetMap,
                    "Window: write the panel's widgets (label, ImGui ID, rectangle) and the window's state as JSON to FILE each frame");
    cmd->add_option("--wif", o->wif, "Window: open this draft (WIF file) on the first woven material, in the draft view");
    cmd->callback([o] {
        checkModeOptions(*o);
        if (o->headless) return runHeadless(*o);
        // The window saves a material or a draft back to the file it opened when its user asks.
        rememberInputs(false);
        PreviewWindowOptions window;
        window.scene = o->scene;
        window.frame = o->frame;
        window.frames = o->frames;
        window.screenshot = o->windowScreenshot;
        window.draft = o->wif;
        window.widgetMap = o->widgetMap;
        window.rendered = o->viewport == "rendered";
        runPreviewWindow(window);
    });
}

}  // namespace woven
