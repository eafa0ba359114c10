#include "preview_window_impl.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "demo_scene.h"
#include "gl_error.h"
#include "image_io.h"
#include "scene_loader.h"
#include "woven_assignment.h"
#include "woven_params_json.h"

namespace woven {

namespace {

// SIGINT, SIGTERM: the window closes at the end of the frame, as if its close button was pressed.
std::atomic<bool> closeRequested{false};
extern "C" void requestClose(int) { closeRequested = true; }

// FNV-1a of an image's bytes, as hexadecimal (JSON's numbers do not hold 64 bits).
std::string checksum(const Image& image) {
    uint64_t hash = 1469598103934665603ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(image.pixels.data());
    for (size_t i = 0; i < image.pixels.size() * sizeof(glm::vec3); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

// Weaving programs write .wif and .WIF alike.
bool isDraftFile(const std::string& path) { return hasExtension(path, ".wif") || hasExtension(path, ".WIF"); }

// A window with the newest core context the driver gives, 4.5 down to 3.3.
GLFWwindow* createWindow(int width, int height) {
    static const int versions[][2] = {{4, 5}, {4, 1}, {3, 3}};
    for (const auto& v : versions) {
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        if (GLFWwindow* window = glfwCreateWindow(width, height, "woven preview", nullptr, nullptr)) return window;
    }
    const char* why = nullptr;
    glfwGetError(&why);
    throw GlError(std::string("could not create an OpenGL 3.3+ core window: ") + (why ? why : "unknown GLFW error"));
}

}  // namespace

std::string besideScene(const std::string& scene, const std::string& suffix, const std::string& fallback) {
    if (scene.empty()) return fallback;
    const std::filesystem::path path(scene);
    return (path.parent_path() / (path.stem().string() + suffix)).string();
}

PreviewWindow::PreviewWindow(const PreviewWindowOptions& options)
    : options_(options), filterWeave_(!options.frame.noFilter) {
    if (!glfwInit()) {
        const char* why = nullptr;
        glfwGetError(&why);
        throw GlError(std::string("could not initialise GLFW (no display? use --headless): ") +
                      (why ? why : "unknown error"));
    }
    try {
        window_ = createWindow(options.frame.width > 0 ? options.frame.width : 1280,
                               options.frame.height > 0 ? options.frame.height : 800);
    } catch (...) {
        glfwTerminate();
        throw;
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    // Installed before ImGui's, which chains to them; each input wakes a resting window.
    glfwSetScrollCallback(window_, onScroll);
    glfwSetDropCallback(window_, onDrop);
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { wake(w); });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { wake(w); });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { wake(w); });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { wake(w); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { wake(w); });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { wake(w); });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    imguiKeyCallback_ = glfwSetKeyCallback(window_, onKey);  // ImGui's, which ours forwards to
    ImGui_ImplOpenGL3_Init("#version 330 core");

    renderer_ = std::make_unique<PreviewRenderer>();
    glGenTextures(1, &renderedTexture_);
    display_ = options.frame.display;
    openScene(options.scene);
    if (!options.draft.empty()) openDraft(options.draft);
    setRenderedView(options.rendered);
}

PreviewWindow::~PreviewWindow() {
    render_.cancel();
    rendered_.stop();
    render_.releaseTexture();
    glDeleteTextures(1, &renderedTexture_);
    fabrics_ = FabricsSection();  // the menu's textures go while the context is current
    renderer_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void PreviewWindow::openScene(const std::string& path) {
    SceneDescription loaded = path.empty() ? wavyClothScene() : loadScene(path, options_.frame.load);
    // The command line's --woven edits name the command line's scene's materials.
    FrameOptions sceneOptions = options_.frame;
    if (path != options_.scene) sceneOptions.woven.clear();
    applySceneOptions(loaded, sceneOptions);
    render_.cancel();
    status_.restartMessages(loaded.warnings);  // printed on stderr as the scene was read
    edits_.emplace(std::move(loaded));
    scenePath_ = path;
    savePath_ = besideScene(path, "-tuned.json", "material.json");
    copyToBuffer(materialPath_, savePath_);
    renderer_->setMeshes(scene());
    picker_.reset();
    pickedMesh_ = -1;
    fabrics_.reset();
    lights_ = PreviewLights::fromScene(scene());
    camera_ = OrbitCamera::forScene(scene());
    // The panel starts on the first woven material, as an edit of its own name (no change yet).
    editIndex_ = -1;
    draft_.close();
    for (const Material& m : scene().materials)
        if (m.woven) {
            editIndex_ = edits_->makeWoven(literalTarget(TargetKind::Material, m.name));
            // A material made from a draft ("wif") opens it in the draft view; one whose threads
            // have colours of their own, its weave drawn as a draft.
            const WovenParams& p = edits_->params(editIndex_);
            if (!m.draft.empty()) {
                std::vector<std::string> warnings;  // printed when the scene was read
                draft_.open(DraftEditor::open(m.draft, warnings), editIndex_, false);
            } else if (!p.warp_colors.empty() || !p.weft_colors.empty()) {
                status_.attempt([&] { showWeaveAsDraft(p, m.name, false); });
            }
            break;
        }
    loadedEnvironment_ = scene().environment.color;
    ++sceneGeneration_;
    history_.reset(materialState());
    // The Render button's settings as `woven render` takes them, but a size neither the command
    // line nor the scene gives is the window's: what it frames.
    RenderSettings settings = frameSettings(scene(), options_.frame);
    int windowWidth = 0, windowHeight = 0;
    glfwGetFramebufferSize(window_, &windowWidth, &windowHeight);
    if (options_.frame.width <= 0 && scene().render.width <= 0) settings.width = std::max(windowWidth, 1);
    if (options_.frame.height <= 0 && scene().render.height <= 0) settings.height = std::max(windowHeight, 1);
    render_.reset(settings, besideScene(path, "-render.png", "render.png"), besideScene(path, "-export.glb", "scene.glb"));
    status_.say("opened " + (path.empty() ? std::string("the procedural cloth") : path));
    glfwSetWindowTitle(window_, ("woven preview - " + (path.empty() ? std::string("cloth") : path)).c_str());
}

void PreviewWindow::openDraft(const std::string& path) {
    WovenParams* p = editedParams();
    if (!p) throw std::runtime_error(path + ": nothing is woven to weave the draft on: click a surface and make it woven");
    std::vector<std::string> warnings;
    DraftEditor editor = DraftEditor::open(path, warnings);
    *p = editor.material(*p);
    draft_.open(std::move(editor), editIndex_, true, path);
    materialEdited();
    applyEdits();
    for (const std::string& w : warnings) status_.warn(w);
    std::string said = "opened " + path;
    if (!warnings.empty())
        said += " (" + std::to_string(warnings.size()) + " warning" + (warnings.size() > 1 ? "s" : "") + ": " +
                warnings.front() + ")";
    status_.say(said);
}

std::string PreviewWindow::editedTarget() const {
    return editIndex_ >= 0 && editIndex_ < int(edits_->edits().size()) ? edits_->edits()[size_t(editIndex_)].target : "";
}

void PreviewWindow::applyFinishedFit() {
    const auto metresPerUv = [&](const std::string& target) -> const std::optional<glm::dvec2>& { return metresPerUvOf(target); };
    const int fitted = fit_.applyFinished(*edits_, metresPerUv, status_);
    if (fitted < 0) return;
    editIndex_ = fitted;
    fabrics_.setChosen(std::nullopt);
    materialEdited();
    applyEdits();
}

WovenParams* PreviewWindow::editedParams() {
    if (editIndex_ < 0 || editIndex_ >= int(edits_->edits().size())) return nullptr;
    return &edits_->params(editIndex_);
}

// The scene's materials from the edits, after any change; the meshes go to the GPU again only
// when a primitive's material index changed (a split, a revert).
void PreviewWindow::applyEdits() {
    status_.attempt([&] {
        if (edits_->apply()) {
            renderer_->setMeshes(scene());
            picker_.reset();
        }
    });
}

// A click: select the primitive under the cursor, as core's renderer sees the preview's view.
void PreviewWindow::pick(glm::vec2 cursor) {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    Camera camera = camera_.camera();
    camera.aspect = float(width) / float(std::max(height, 1));
    if (!status_.attempt([&] { pickedMesh_ = picker_.pick(scene(), camera, {width, height}, cursor); })) pickedMesh_ = -1;
    // Offer the most specific target: the node that holds the primitive.
    if (pickedMesh_ >= 0) targetChoice_ = int(edits_->targetsFor(pickedMesh_).size()) - 1;
}

void PreviewWindow::wake(GLFWwindow* window) { ++static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window))->inputs_; }

void PreviewWindow::onScroll(GLFWwindow* window, double, double dy) {
    wake(window);
    static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window))->scroll_ += dy;
}

void PreviewWindow::onDrop(GLFWwindow* window, int count, const char** paths) {
    wake(window);
    auto* self = static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->droppedPaths_.emplace_back(paths[i]);
}

void PreviewWindow::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    wake(window);
    auto* self = static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window));
    auto& pressed = self->pressedSinceFrame_;
    if (action == GLFW_PRESS) pressed.push_back(key);
    // Once a key went down since the last frame, every release waits for that frame: the release
    // of a modifier held since an earlier frame (Ctrl+Shift+Z's Shift, when Z came in the next
    // batch of events) would otherwise reach ImGui before the frame that reads Z with it.
    if (action == GLFW_RELEASE && !pressed.empty()) {
        self->deferredReleases_.emplace_back(key, scancode, mods);
        return;
    }
    if (self->imguiKeyCallback_) self->imguiKeyCallback_(window, key, scancode, action, mods);
}

namespace {

bool isModifier(int key) {
    return key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT || key == GLFW_KEY_LEFT_CONTROL ||
           key == GLFW_KEY_RIGHT_CONTROL || key == GLFW_KEY_LEFT_ALT || key == GLFW_KEY_RIGHT_ALT ||
           key == GLFW_KEY_LEFT_SUPER || key == GLFW_KEY_RIGHT_SUPER;
}

}  // namespace

// After ImGui::NewFrame(), which saw the keys down. A modifier stays down for the whole frame,
// released before the next NewFrame() (releaseDeferredModifiers): ImGui 1.86 asserts that the
// modifiers do not change within a frame (a quick Ctrl+A in a text field aborted the window),
// and the shortcut needs it held while the frame reads the key it modifies.
void PreviewWindow::releaseDeferredKeys() {
    pressedSinceFrame_.clear();
    std::vector<glm::ivec3> releases;
    releases.swap(deferredReleases_);
    for (const glm::ivec3& r : releases) {
        if (isModifier(r.x)) deferredModifierReleases_.push_back(r);
        else if (imguiKeyCallback_) imguiKeyCallback_(window_, r.x, r.y, GLFW_RELEASE, r.z);
    }
}

void PreviewWindow::releaseDeferredModifiers() {
    std::vector<glm::ivec3> releases;
    releases.swap(deferredModifierReleases_);
    for (const glm::ivec3& r : releases)
        if (imguiKeyCallback_) imguiKeyCallback_(window_, r.x, r.y, GLFW_RELEASE, r.z);
}

void PreviewWindow::handleMouse() {
    glm::dvec2 cursor;
    glfwGetCursorPos(window_, &cursor.x, &cursor.y);
    const glm::vec2 delta(cursor - lastCursor_);
    lastCursor_ = cursor;
    const double scroll = scroll_;
    scroll_ = 0.0;
    const bool leftDown = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    steering_ = false;
    if (!leftDown && pressedAt_) {
        // Released where it was pressed: a click, not the end of an orbit.
        if (glm::length(cursor - *pressedAt_) < 3.0) pick(glm::vec2(cursor));
        pressedAt_.reset();
    }
    if (ImGui::GetIO().WantCaptureMouse) return;
    if (leftDown && !pressedAt_) pressedAt_ = cursor;
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    const float h = float(std::max(height, 1));
    const bool moved = delta != glm::vec2(0.0f);
    bool changed = scroll != 0.0;
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && moved) {
        camera_.orbit(-delta.x * 3.0f / h, delta.y * 3.0f / h);
        changed = true;
    } else if ((glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS) &&
               moved) {
        camera_.pan(delta.x / h, delta.y / h);
        changed = true;
    }
    if (scroll != 0.0) camera_.zoom(std::pow(0.9f, float(scroll)));
    // The rendered frame is of the old view: moving the camera goes back to the live preview.
    if (changed) render_.hide();
    // A held button steers even while the cursor rests, so a pause in a drag is no full frame.
    steering_ = changed || pressedAt_ || glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
}

void PreviewWindow::writeWindowScreenshot(const std::string& path) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    std::vector<uint8_t> bytes(size_t(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    // writePng takes linear radiance and sRGB-encodes it: decode the displayed bytes, bottom row
    // first, and write them back with no curve.
    Image image;
    image.width = width;
    image.height = height;
    image.pixels.resize(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint8_t* b = &bytes[(size_t(height - 1 - y) * width + x) * 4];
            image.at(x, y) = glm::vec3(srgbToLinear(b[0] / 255.0f), srgbToLinear(b[1] / 255.0f),
                                       srgbToLinear(b[2] / 255.0f));
        }
    writePng(path, image, {0.0f, ToneMap::Clamp});
}

// The frame's widgets and what the window test waits on, written whole (FILE.tmp, renamed) so a
// reader never sees half a frame.
void PreviewWindow::writeWidgetMap(const std::string& path) {
    nlohmann::json map = widgets_.json();
    int x = 0, y = 0, width = 0, height = 0;
    glfwGetWindowPos(window_, &x, &y);
    glfwGetWindowSize(window_, &width, &height);
    // The edited material as the panel shows it: its fabric, repeat and measures.
    nlohmann::json material = nullptr;
    if (const WovenParams* p = editedParams()) {
        const std::string& target = edits_->edits()[size_t(editIndex_)].target;
        const ChosenFabric* chosen = fabrics_.chosenFor(target);
        material = {{"target", target},
                    {"fabric", chosen ? nlohmann::json(chosen->name) : nlohmann::json(nullptr)},
                    {"repeat", {p->repeat.x, p->repeat.y}},
                    {"ex", p->ex},
                    {"warp_color", {p->warp_color.x, p->warp_color.y, p->warp_color.z}},
                    {"pattern", {p->pattern.x, p->pattern.y, p->pattern.z}},
                    {"tile_rows", p->tile.size()},
                    {"draft_open", draft_.openFor(editIndex_)},
                    {"measures", fabrics_.measures()},
                    // Every parameter, for the tests to tell whether an undo restored them all.
                    {"params", paramsToJson(*p)}};
    }
    map["state"] = {
        {"frame", frame_},
        {"window", {{"pos", {x, y}}, {"size", {width, height}}}},
        {"status", status_.text()},
        {"messages", status_.messages()},
        {"interacting", interacting_},
        {"resolution_scale", resolution_.scale()},
        {"refinement", std::min(refinement_ + 1, kRefinementFrames)},
        {"view", {{"since", begunView_.frame}, {"checksum", begunView_.checksum},
                  {"mean", {begunView_.mean.r, begunView_.mean.g, begunView_.mean.b}}}},
        {"material", material},
        {"history", {{"undo", history_.canUndo()}, {"redo", history_.canRedo()}}},
        {"render", render_.settingsState()},
        {"fit", fit_.state()},
        {"rendered", renderedViewState()},
        {"final", render_.frameState()},
    };
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp);
        out << map.dump() << "\n";
        if (!out) throw std::runtime_error(tmp + ": could not write the widget map");
    }
    std::filesystem::rename(tmp, path);
}

// Whether the next frame may differ from the last with no input: a render, the Rendered view's
// passes or a fit under way, the view still at a reduced size, a drag held, or a counted run
// (--frames).
bool PreviewWindow::busy() const {
    const bool refining = refinement_ < kRefinementFrames - 1 && !render_.shown() && !renderedView_;
    return render_.running() || fit_.running() || (renderedView_ && rendered_.running()) || interacting_ || refining ||
           resolution_.scale() < 1.0f || options_.frames > 0 || !deferredReleases_.empty() ||
           !deferredModifierReleases_.empty();
}

// Waits, drawing nothing, until an input arrives or the window has work; a few frames follow each
// input or the end of work, for ImGui's hover and popups to settle. Woken each 0.25 s to see a
// signal or a background job start. Returns whether it waited.
bool PreviewWindow::restUntilNeeded() {
    constexpr double kSettleSeconds = 0.5;
    constexpr int kSettleFrames = 3;
    const double now = glfwGetTime();
    if (busy() || inputs_ != inputsSeen_) {
        inputsSeen_ = inputs_;
        settleUntil_ = now + kSettleSeconds;
        settleFrames_ = kSettleFrames;
        return false;
    }
    if (settleFrames_ > 0 || now < settleUntil_) {
        --settleFrames_;
        return false;
    }
    // A focused text field's cursor blinks: a frame each 0.4 s while one is.
    const double restStart = glfwGetTime();
    const bool typing = ImGui::GetIO().WantTextInput;
    while (!closeRequested && !glfwWindowShouldClose(window_) && inputs_ == inputsSeen_ && !busy() &&
           !(typing && glfwGetTime() - restStart >= 0.4))
        glfwWaitEventsTimeout(typing ? 0.1 : 0.25);
    inputsSeen_ = inputs_;
    settleUntil_ = glfwGetTime() + kSettleSeconds;
    settleFrames_ = kSettleFrames;
    return true;
}

// The preview's view: its next refinement frame rendered where one is due, and shown.
void PreviewWindow::drawPreviewView(int width, int height, double now) {
    Camera camera = camera_.camera();
    camera.aspect = float(width) / float(height);
    PreviewOptions preview;
    preview.filterWeave = filterWeave_;
    preview.shadows = shadows_;
    preview.traceBounce = !interacting_;
    status_.attempt([&] {
        const glm::ivec2 size = resolution_.frameSize({width, height}, interacting_, now);
        const RefinedView view{camera.cameraToWorld, camera.yfov, size, sceneGeneration_, filterWeave_, shadows_};
        // Input (a pointer move, a click, a key) holds the refinement, the mean so far
        // shown, until it has paused for kInputPause: a refinement frame on software GL
        // takes a second, which each hover and click of the panel would wait for, and the
        // events of one gesture come tens of milliseconds apart. So does the Render
        // button's frame, whose cores the refinement would take. A view that changed is
        // rendered at once.
        constexpr double kInputPause = 0.25;
        const bool sameView = !interacting_ && view == refinedView_;
        const bool held = sameView && (now - lastInputAt_ < kInputPause || render_.running());
        if (!held) refinement_ = sameView ? refinement_ + 1 : 0;
        refinedView_ = view;
        // Once the mean is complete the view is shown again as it is, not rendered.
        if (refinement_ < kRefinementFrames && !held) {
            preview.refinement = refinement_;
            preview.pixelOffset = refinementOffset(refinement_);
            renderer_->render(scene(), lights_, camera, size, preview);
            // Its first frame is a function of the view alone: the window tests need not
            // wait for the refinement to end to tell whether an edit changed the view.
            if (refinement_ == 0 && size == glm::ivec2(width, height) && !options_.widgetMap.empty()) {
                const Image radiance = renderer_->radiance();
                begunView_ = {frame_, checksum(radiance), meanColour(radiance)};
            }
        }
        renderer_->display(0, {0, 0}, {width, height}, display_);
    });
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

void PreviewWindow::run() {
    closeRequested = false;
    auto previousInt = std::signal(SIGINT, requestClose);
    auto previousTerm = std::signal(SIGTERM, requestClose);
    glfwGetCursorPos(window_, &lastCursor_.x, &lastCursor_.y);
    double frameStart = glfwGetTime();
    for (frame_ = 1; !glfwWindowShouldClose(window_); ++frame_) {
        glfwPollEvents();
        bool rested = restUntilNeeded();
        if (restWhileRendering()) rested = true;
        const double now = glfwGetTime();
        if (inputs_ != inputsDrawn_) lastInputAt_ = now;
        inputsDrawn_ = inputs_;
        if (frame_ > 1 && !rested) resolution_.frameTook(now - frameStart);
        frameStart = now;
        std::vector<std::string> dropped;
        dropped.swap(droppedPaths_);
        for (const std::string& path : dropped) {
            status_.attempt([&] {
                if (isDraftFile(path)) openDraft(path);
                else openScene(path);
            });
        }
        render_.poll(display_);

        releaseDeferredModifiers();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        releaseDeferredKeys();
        handleShortcuts();
        handleViewKeys();
        widgets_.beginFrame();
        setCurrentWidgetMap(&widgets_);
        drawPanel();
        drawDraftWindow();
        commitCompletedEdit();
        setCurrentWidgetMap(nullptr);
        widgets_.warnClashes();
        render_.drawInView();
        handleMouse();
        // A focused text field is no interaction: the view stays sharp while typing.
        interacting_ = steering_ || panelInteracting();
        const bool finalShown = render_.shown();
        if (renderedView_ && !finalShown) drawRenderedView();
        ImGui::Render();

        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (width > 0 && height > 0 && !finalShown && !renderedView_) drawPreviewView(width, height, now);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        // A signal ends the loop after this frame, which is then the last (and its screenshot).
        const bool last = (options_.frames > 0 && frame_ >= options_.frames) || closeRequested;
        if (last && !options_.screenshot.empty()) writeWindowScreenshot(options_.screenshot);
        glfwSwapBuffers(window_);
        if (!options_.widgetMap.empty()) writeWidgetMap(options_.widgetMap);
        if (last) break;
    }
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
}

void runPreviewWindow(const PreviewWindowOptions& options) {
    PreviewWindow window(options);
    window.run();
}

}  // namespace woven