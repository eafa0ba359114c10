#include "preview_window.h"

#include <epoxy/gl.h>
// epoxy must come first: GLFW would otherwise include the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "demo_scene.h"
#include "draft_material.h"
#include "draft_view.h"
#include "final_render.h"
#include "gl_error.h"
#include "image_io.h"
#include "interactive_resolution.h"
#include "material_file.h"
#include "orbit_camera.h"
#include "preview_renderer.h"
#include "scene_export.h"
#include "scene_loader.h"
#include "scene_picker.h"
#include "uv_scale.h"
#include "weave_presets.h"
#include "woven_assignment.h"
#include "woven_edits.h"

namespace woven {

namespace {

// ImGui's text fields edit fixed buffers.
template <size_t N>
void copyToBuffer(char (&buffer)[N], const std::string& text) {
    std::snprintf(buffer, N, "%s", text.c_str());
}

bool hasExtension(const std::string& path, const char* ext) {
    const size_t n = std::char_traits<char>::length(ext);
    return path.size() >= n && path.compare(path.size() - n, n, ext) == 0;
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

// RGBA8 of `image` through the display transform of PNG output.
std::vector<uint8_t> displayBytes(const Image& image, const DisplayTransform& transform) {
    std::vector<uint8_t> bytes(image.pixels.size() * 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::u8vec3 c = displayColor(image.pixels[i], transform);
        bytes[4 * i] = c.r;
        bytes[4 * i + 1] = c.g;
        bytes[4 * i + 2] = c.b;
        bytes[4 * i + 3] = 255;
    }
    return bytes;
}


class PreviewWindow {
public:
    explicit PreviewWindow(const PreviewWindowOptions& options);
    ~PreviewWindow();
    void run();

private:
    void openScene(const std::string& path);
    void openDraft(const std::string& path);
    void handleMouse();
    void pick(glm::vec2 cursor);
    void drawPanel();
    void drawSelection();
    void drawMaterialControls(WovenParams& p);
    void drawDraftControls(WovenParams& p);
    void drawDraftWindow();
    void applyEdits();
    void drawLightControls();
    void drawRenderControls();
    void updateFinalTexture(const FilmImage& film);
    void drawFinalImage();
    void writeWindowScreenshot(const std::string& path);
    WovenParams* editedParams();
    SceneDescription& scene() { return edits_->sceneForLighting(); }

    static void onScroll(GLFWwindow* window, double, double dy);
    static void onDrop(GLFWwindow* window, int count, const char** paths);

    PreviewWindowOptions options_;
    GLFWwindow* window_ = nullptr;
    std::unique_ptr<PreviewRenderer> renderer_;
    std::optional<WovenEdits> edits_;  // the scene as loaded, with the window's "make woven" edits
    std::string scenePath_;
    PreviewLights lights_;
    OrbitCamera camera_;
    ScenePicker picker_;
    int pickedMesh_ = -1;     // the primitive last clicked
    int targetChoice_ = 0;    // which of its targets the selection panel offers
    int editIndex_ = -1;      // the edit the panel tunes
    int presetIndex_ = -1;
    DisplayTransform display_;
    bool filterWeave_ = true;
    bool shadows_ = true;
    double scroll_ = 0.0;
    std::vector<std::string> droppedPaths_;
    glm::dvec2 lastCursor_{0.0};
    std::optional<glm::dvec2> pressedAt_;  // where the left button went down, while it is down
    bool steering_ = false;                // the camera is being dragged or zoomed
    InteractiveResolution resolution_;
    std::string status_;
    char materialPath_[512] = "material.json";
    char imagePath_[512] = "render.png";
    char exportPath_[512] = "scene.glb";

    // The draft of edit draftEdit_: every edit in the draft view is applied to that edit's
    // parameters at once, so the next frame shows it.
    std::optional<DraftEditor> draft_;
    int draftEdit_ = -1;
    DraftView draftView_;
    char draftPath_[512] = "draft.wif";

    FinalRender final_;
    std::optional<FilmImage> finalImage_;
    GLuint finalTexture_ = 0;
    bool showFinal_ = false;
    RenderSettings render_;  // the Render button's, but for the camera
};

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
    // Installed before ImGui's, which chains to them.
    glfwSetScrollCallback(window_, onScroll);
    glfwSetDropCallback(window_, onDrop);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    renderer_ = std::make_unique<PreviewRenderer>();
    glGenTextures(1, &finalTexture_);
    display_ = options.frame.display;
    openScene(options.scene);
    if (!options.draft.empty()) openDraft(options.draft);
}

PreviewWindow::~PreviewWindow() {
    final_.cancel();
    glDeleteTextures(1, &finalTexture_);
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
    final_.cancel();
    edits_.emplace(std::move(loaded));
    scenePath_ = path;
    renderer_->setMeshes(scene());
    picker_.reset();
    pickedMesh_ = -1;
    lights_ = PreviewLights::fromScene(scene());
    camera_ = OrbitCamera::forScene(scene());
    // The panel starts on the first woven material, as an edit of its own name (no change yet).
    editIndex_ = -1;
    draft_.reset();
    for (const Material& m : scene().materials)
        if (m.woven) {
            editIndex_ = edits_->makeWoven(literalTarget(TargetKind::Material, m.name));
            // A material made from a draft ("wif") opens it in the draft view.
            if (!m.draft.empty()) {
                std::vector<std::string> warnings;  // printed when the scene was read
                draft_ = DraftEditor::open(m.draft, warnings);
                draftEdit_ = editIndex_;
                copyToBuffer(draftPath_, draft_->name());
            }
            break;
        }
    presetIndex_ = -1;
    showFinal_ = false;
    // The Render button's settings as `woven render` takes them, but a size neither the command
    // line nor the scene gives is the window's: what it frames.
    render_ = frameSettings(scene(), options_.frame);
    int windowWidth = 0, windowHeight = 0;
    glfwGetFramebufferSize(window_, &windowWidth, &windowHeight);
    if (options_.frame.width <= 0 && scene().render.width <= 0) render_.width = std::max(windowWidth, 1);
    if (options_.frame.height <= 0 && scene().render.height <= 0) render_.height = std::max(windowHeight, 1);
    status_ = "opened " + (path.empty() ? std::string("the procedural cloth") : path);
    glfwSetWindowTitle(window_, ("woven preview - " + (path.empty() ? std::string("cloth") : path)).c_str());
}

void PreviewWindow::openDraft(const std::string& path) {
    WovenParams* p = editedParams();
    if (!p) throw std::runtime_error(path + ": nothing is woven to weave the draft on: click a surface and make it woven");
    std::vector<std::string> warnings;
    DraftEditor editor = DraftEditor::open(path, warnings);
    *p = editor.material(*p);
    draft_ = std::move(editor);
    draftEdit_ = editIndex_;
    presetIndex_ = -1;
    applyEdits();
    copyToBuffer(draftPath_, path);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    status_ = "opened " + path;
    if (!warnings.empty())
        status_ += " (" + std::to_string(warnings.size()) + " warning" + (warnings.size() > 1 ? "s" : "") + ": " +
                   warnings.front() + ")";
}

WovenParams* PreviewWindow::editedParams() {
    if (editIndex_ < 0 || editIndex_ >= int(edits_->edits().size())) return nullptr;
    return &edits_->params(editIndex_);
}

// The scene's materials from the edits, after any change; the meshes go to the GPU again only
// when a primitive's material index changed (a split, a revert).
void PreviewWindow::applyEdits() {
    try {
        if (edits_->apply()) {
            renderer_->setMeshes(scene());
            picker_.reset();
        }
    } catch (const std::exception& e) {
        status_ = e.what();
    }
}

// A click: select the primitive under the cursor, as core's renderer sees the preview's view.
void PreviewWindow::pick(glm::vec2 cursor) {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    Camera camera = camera_.camera();
    camera.aspect = float(width) / float(std::max(height, 1));
    try {
        pickedMesh_ = picker_.pick(scene(), camera, {width, height}, cursor);
    } catch (const std::exception& e) {
        status_ = e.what();
        pickedMesh_ = -1;
    }
    // Offer the most specific target: the node that holds the primitive.
    if (pickedMesh_ >= 0) targetChoice_ = int(edits_->targetsFor(pickedMesh_).size()) - 1;
}

void PreviewWindow::onScroll(GLFWwindow* window, double, double dy) {
    static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window))->scroll_ += dy;
}

void PreviewWindow::onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<PreviewWindow*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->droppedPaths_.emplace_back(paths[i]);
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
    if (changed) showFinal_ = false;
    // A held button steers even while the cursor rests, so a pause in a drag is no full frame.
    steering_ = changed || pressedAt_ || glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
}

void PreviewWindow::drawMaterialControls(WovenParams& p) {
    const auto& presets = weavePresets();
    const char* presetName = presetIndex_ >= 0 ? presets[presetIndex_].name.c_str() : "(custom)";
    if (ImGui::BeginCombo("weave preset", presetName)) {
        for (size_t i = 0; i < presets.size(); ++i)
            if (ImGui::Selectable(presets[i].name.c_str(), int(i) == presetIndex_)) {
                presetIndex_ = int(i);
                applyPreset(presets[i], p);
            }
        ImGui::EndCombo();
    }
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) continue;  // the tile and the per-thread lists: the draft view
        char* field = reinterpret_cast<char*>(&p) + info.offset;
        ImGui::PushID(info.name);
        const ImGuiSliderFlags flags = info.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
        switch (info.type) {
        case ParamType::Float:
            ImGui::SliderFloat(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Int:
            ImGui::SliderInt(info.label, reinterpret_cast<int*>(field), int(info.min), int(info.max));
            break;
        case ParamType::Vec2:
            ImGui::SliderFloat2(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Vec3:
            ImGui::ColorEdit3(info.label, reinterpret_cast<float*>(field), ImGuiColorEditFlags_Float);
            break;
        case ParamType::IVec3: {
            int* v = reinterpret_cast<int*>(field);
            if (ImGui::InputInt3(info.label, v)) {
                for (int c = 0; c < 3; ++c) v[c] = std::clamp(v[c], int(info.min), int(info.max));
                p.tile.clear();  // an edited (i, j, k) replaces a hand-drawn tile
                presetIndex_ = -1;
            }
            break;
        }
        default: break;
        }
        ImGui::PopID();
    }
    try {
        validate(p);
    } catch (const std::exception& e) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", e.what());
    }

    ImGui::InputText("scene file", materialPath_, sizeof materialPath_);
    const std::string& target = edits_->edits()[size_t(editIndex_)].target;
    if (ImGui::Button("Save materials")) {
        // Every edit under its target, as a scene file's "materials" says it.
        try {
            const bool gltf = hasExtension(scenePath_, ".gltf") || hasExtension(scenePath_, ".glb");
            for (const WovenEdit& e : edits_->edits()) saveMaterial(materialPath_, e.target, e.params, gltf ? scenePath_ : "");
            status_ = std::string("saved ") + materialPath_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Load material")) {
        try {
            std::vector<std::string> warnings;
            const MaterialJson read = loadMaterial(materialPath_, target, p, warnings);
            p = read.params;
            if (read.threadsPerCm) p.repeat = repeatForThreadsPerCm(scene(), edits_->meshesOf(target), *read.threadsPerCm);
            presetIndex_ = -1;
            status_ = std::string("loaded ") + materialPath_;
            for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
            if (!read.wif.empty()) {
                draft_ = DraftEditor::open(read.wif, warnings);
                draftEdit_ = editIndex_;
                copyToBuffer(draftPath_, read.wif);
            }
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    drawDraftControls(p);
}

void PreviewWindow::drawDraftControls(WovenParams& p) {
    ImGui::Separator();
    ImGui::InputText("draft file", draftPath_, sizeof draftPath_);
    if (ImGui::Button("Open draft")) {
        try {
            openDraft(draftPath_);
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    if (!draft_ || draftEdit_ != editIndex_) {
        ImGui::SameLine();
        ImGui::TextDisabled("(or drop a .wif on the window)");
        return;
    }
    ImGui::SameLine();
    if (ImGui::Button("Save WIF")) {
        try {
            draft_->save(draftPath_);
            status_ = std::string("saved ") + draftPath_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    // "scale": "draft": the draft's threads per centimetre on this mesh.
    if (ImGui::Button("Real scale")) {
        try {
            const std::string& target = edits_->edits()[size_t(editIndex_)].target;
            p.repeat = repeatForThreadsPerCm(scene(), edits_->meshesOf(target),
                                             draftThreadsPerCm(draft_->draft(), draft_->name()));
            validate(p);
            status_ = "repeat from the draft's spacing";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    if (ImGui::Button("Save material with draft")) {
        try {
            const bool gltf = hasExtension(scenePath_, ".gltf") || hasExtension(scenePath_, ".glb");
            const std::string wif = saveMaterialWithDraft(materialPath_, edits_->edits()[size_t(editIndex_)].target, p,
                                                          gltf ? scenePath_ : "", *draft_);
            copyToBuffer(draftPath_, wif);
            status_ = std::string("saved ") + materialPath_ + " and " + wif;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
}

// The draft view of the material the draft belongs to, beside the panel.
void PreviewWindow::drawDraftWindow() {
    if (!draft_ || draftEdit_ < 0 || draftEdit_ >= int(edits_->edits().size())) return;
    WovenParams* woven = &edits_->params(draftEdit_);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(456, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(display.x - 464, 200.0f), display.y * 0.45f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Draft");
    try {
        if (draftView_.draw(*draft_, woven->warp_color, woven->weft_color)) {
            *woven = draft_->material(*woven);
            presetIndex_ = -1;
            showFinal_ = false;  // the rendered frame is of the old cloth
            applyEdits();
        }
    } catch (const std::exception& e) {
        status_ = e.what();
    }
    ImGui::End();
}

// Edits the scene's own lights, so the Render button sees the same lighting as the preview.
void PreviewWindow::drawLightControls() {
    static const char* typeNames[] = {"point", "spot", "directional"};
    bool changed = false;
    for (size_t i = 0; i < scene().lights.size(); ++i) {
        PunctualLight& light = scene().lights[i];
        ImGui::PushID(int(i));
        ImGui::Text("light %zu (%s)", i, typeNames[int(light.type)]);
        changed |= ImGui::ColorEdit3("intensity", &light.intensity.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        if (light.type == PunctualLight::Type::Point)
            changed |= ImGui::DragFloat3("position", &light.position.x, 0.05f);
        if (light.type != PunctualLight::Type::Point && ImGui::SliderFloat3("direction", &light.direction.x, -1.0f, 1.0f)) {
            if (glm::length(light.direction) < 1e-3f) light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
            light.direction = glm::normalize(light.direction);
            changed = true;
        }
        ImGui::PopID();
    }
    changed |= ImGui::ColorEdit3("environment", &scene().environment.color.x,
                                 ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    if (changed) lights_ = PreviewLights::fromScene(scene());
}

void PreviewWindow::drawRenderControls() {
    ImGui::InputInt2("render size", &render_.width);
    render_.width = std::clamp(render_.width, 1, 16384);
    render_.height = std::clamp(render_.height, 1, 16384);
    ImGui::InputInt("spp", &render_.spp);
    render_.spp = std::clamp(render_.spp, 1, 1 << 20);
    ImGui::InputDouble("noise threshold", &render_.noiseThreshold, 0.01, 0.05, "%.3f");
    render_.noiseThreshold = std::clamp(render_.noiseThreshold, 0.0, 1.0);
    if (ImGui::BeginCombo("integrator", render_.integrator.c_str())) {
        for (const char* name : kIntegratorNames)
            if (ImGui::Selectable(name, render_.integrator == name)) render_.integrator = name;
        ImGui::EndCombo();
    }
    if (ImGui::Button("Render")) {
        RenderSettings settings = render_;
        settings.camera = camera_.camera();
        final_.start(scene(), settings);
        finalImage_.reset();
        showFinal_ = true;
    }
    if (final_.running()) {
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) final_.cancel();
    }
    // Export: the scene as the window shows it, through its camera, woven materials baked.
    ImGui::SameLine();
    if (ImGui::Button("Export")) {
        SceneDescription shown = scene();
        shown.camera = camera_.camera();
        shown.hasCamera = true;
        try {
            const std::vector<std::string> warnings = exportScene(shown, exportPath_, ExportOptions{});
            for (const std::string& w : warnings) std::cerr << "warning: " << exportPath_ << ": " << w << "\n";
            status_ = "exported " + std::string(exportPath_) + (warnings.empty() ? "" : " (" + std::to_string(warnings.size()) + " warnings on stderr)");
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText("##export file", exportPath_, sizeof exportPath_);
    if (final_.running() || finalImage_)
        ImGui::ProgressBar(final_.fractionDone(), ImVec2(-1.0f, 0.0f), final_.progressText().c_str());
    if (!final_.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", final_.error().c_str());
    if (!finalImage_) return;
    ImGui::Checkbox("show the rendered frame", &showFinal_);
    ImGui::InputText("image file", imagePath_, sizeof imagePath_);
    const bool png = ImGui::Button("Save PNG");
    ImGui::SameLine();
    const bool exr = ImGui::Button("Save EXR");
    if (png || exr) {
        std::string path = imagePath_;
        const size_t dot = path.find_last_of('.');
        path = (dot == std::string::npos ? path : path.substr(0, dot)) + (png ? ".png" : ".exr");
        try {
            writeFrame(path, finalImage_->exr(), display_);
            status_ = "saved " + path;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
}

// What the last click picked, the targets that name it, and "make woven" / "revert".
void PreviewWindow::drawSelection() {
    if (pickedMesh_ < 0 || pickedMesh_ >= int(scene().meshes.size())) {
        ImGui::TextWrapped("Click a surface to select it.");
        return;
    }
    const Mesh& mesh = scene().meshes[size_t(pickedMesh_)];
    std::string path;
    for (const std::string& node : mesh.nodePath) path += (path.empty() ? "" : " > ") + node;
    ImGui::TextWrapped("node %s", path.c_str());
    ImGui::TextWrapped("mesh %s", mesh.meshName.c_str());
    ImGui::TextWrapped("material %s", mesh.material >= 0 ? scene().materials[size_t(mesh.material)].name.c_str() : "(none)");
    const std::vector<std::string> targets = edits_->targetsFor(pickedMesh_);
    targetChoice_ = std::clamp(targetChoice_, 0, int(targets.size()) - 1);
    if (ImGui::BeginCombo("target", targets[size_t(targetChoice_)].c_str())) {
        for (size_t i = 0; i < targets.size(); ++i)
            if (ImGui::Selectable(targets[i].c_str(), int(i) == targetChoice_)) targetChoice_ = int(i);
        ImGui::EndCombo();
    }
    const std::string& target = targets[size_t(targetChoice_)];
    if (ImGui::Button("Make woven")) {
        try {
            editIndex_ = edits_->makeWoven(target);
            presetIndex_ = -1;
            applyEdits();
            status_ = "made " + target + " woven";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Revert")) {
        const std::string current = editIndex_ >= 0 ? edits_->edits()[size_t(editIndex_)].target : "";
        if (edits_->revert(target)) {
            editIndex_ = -1;
            for (size_t i = 0; i < edits_->edits().size(); ++i)
                if (edits_->edits()[i].target == current) editIndex_ = int(i);
            applyEdits();
            status_ = "reverted " + target;
        } else {
            status_ = target + " has no edit to revert";
        }
    }
}

void PreviewWindow::drawPanel() {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(440, ImGui::GetIO().DisplaySize.y - 16), ImGuiCond_FirstUseEver);
    ImGui::Begin("woven");
    ImGui::PushItemWidth(-200.0f);  // room for the paper's long labels
    ImGui::Text("%s", scenePath_.empty() ? "procedural cloth" : scenePath_.c_str());
    ImGui::Text("%.1f ms/frame, drawn at %.0f%%", 1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f),
                100.0f * resolution_.scale());
    static const char* const toneMaps[] = {"clamp", "reinhard", "aces"};  // core's ToneMap order
    int toneMap = int(display_.toneMap);
    const bool exposureChanged = ImGui::SliderFloat("exposure", &display_.exposure, -8.0f, 8.0f, "%.2f stops");
    const bool toneMapChanged = ImGui::Combo("tone map", &toneMap, toneMaps, IM_ARRAYSIZE(toneMaps));
    display_.toneMap = ToneMap(toneMap);
    if ((exposureChanged || toneMapChanged) && finalImage_) updateFinalTexture(*finalImage_);
    ImGui::Checkbox("filter distant weave", &filterWeave_);
    ImGui::SameLine();
    ImGui::Checkbox("shadows", &shadows_);
    if (ImGui::Button("Frame scene")) {
        const SceneBox box = sceneBounds(scene());
        camera_ = OrbitCamera::around(framingCamera(box, camera_.camera().yfov), box);
    }

    if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) drawSelection();
    if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        const auto& edits = edits_->edits();
        if (ImGui::BeginCombo("woven", editIndex_ >= 0 ? edits[size_t(editIndex_)].target.c_str() : "(none: click a surface)")) {
            for (size_t i = 0; i < edits.size(); ++i)
                if (ImGui::Selectable(edits[i].target.c_str(), int(i) == editIndex_)) editIndex_ = int(i), presetIndex_ = -1;
            ImGui::EndCombo();
        }
        if (WovenParams* p = editedParams()) {
            drawMaterialControls(*p);
            applyEdits();
        }
    }
    if (ImGui::CollapsingHeader("Lights")) drawLightControls();
    if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) drawRenderControls();
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
}

void PreviewWindow::updateFinalTexture(const FilmImage& film) {
    const std::vector<uint8_t> bytes = displayBytes(film.radiance, display_);
    glBindTexture(GL_TEXTURE_2D, finalTexture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, film.radiance.width, film.radiance.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 bytes.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

// The rendered frame, letterboxed over the preview (row 0 of the image is its top).
void PreviewWindow::drawFinalImage() {
    if (!showFinal_ || !finalImage_) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float imageAspect = float(finalImage_->radiance.width) / float(finalImage_->radiance.height);
    ImVec2 size(display.x, display.x / imageAspect);
    if (size.y > display.y) size = ImVec2(display.y * imageAspect, display.y);
    const ImVec2 lo((display.x - size.x) * 0.5f, (display.y - size.y) * 0.5f);
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddRectFilled(ImVec2(0, 0), display, IM_COL32(0, 0, 0, 255));
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(finalTexture_)), lo,
                   ImVec2(lo.x + size.x, lo.y + size.y));
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

void PreviewWindow::run() {
    glfwGetCursorPos(window_, &lastCursor_.x, &lastCursor_.y);
    double frameStart = glfwGetTime();
    for (int frame = 1; !glfwWindowShouldClose(window_); ++frame) {
        const double now = glfwGetTime();
        if (frame > 1) resolution_.frameTook(now - frameStart);
        frameStart = now;
        glfwPollEvents();
        std::vector<std::string> dropped;
        dropped.swap(droppedPaths_);
        for (const std::string& path : dropped) {
            try {
                if (isDraftFile(path)) openDraft(path);
                else openScene(path);
            } catch (const std::exception& e) {
                status_ = e.what();
            }
        }
        if (std::optional<FilmImage> snapshot = final_.newSnapshot()) {
            finalImage_ = std::move(snapshot);
            updateFinalTexture(*finalImage_);
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        drawPanel();
        drawDraftWindow();
        drawFinalImage();
        handleMouse();
        ImGui::Render();

        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (width > 0 && height > 0 && !(showFinal_ && finalImage_)) {
            Camera camera = camera_.camera();
            camera.aspect = float(width) / float(height);
            PreviewOptions preview;
            preview.filterWeave = filterWeave_;
            preview.shadows = shadows_;
            try {
                const bool interacting = steering_ || ImGui::IsAnyItemActive();
                renderer_->render(scene(), lights_, camera, resolution_.frameSize({width, height}, interacting, now),
                                  preview);
                renderer_->display(0, {0, 0}, {width, height}, display_);
            } catch (const std::exception& e) {
                status_ = e.what();  // e.g. a shader variant that fails to compile
            }
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, width, height);
        }
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

        const bool last = options_.frames > 0 && frame >= options_.frames;
        if (last && !options_.screenshot.empty()) writeWindowScreenshot(options_.screenshot);
        glfwSwapBuffers(window_);
        if (last) break;
    }
}

}  // namespace

void runPreviewWindow(const PreviewWindowOptions& options) {
    PreviewWindow window(options);
    window.run();
}

}  // namespace woven
