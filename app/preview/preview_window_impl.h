#pragma once
// The previewer window's class, private to app/preview: its loop and mouse handling are in
// preview_window.cpp, its ImGui panel's sections in panel.cpp (the panel, lights),
// material_panel.cpp (selection, material, draft), and the sections that are objects of their
// own: render_section.h (the Render button), fit_section.h (woven fit), fabrics_section.h.
#include <epoxy/gl.h>
// epoxy must come first: GLFW would otherwise include the system GL header.
#include <GLFW/glfw3.h>

#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draft_editor.h"
#include "draft_section.h"
#include "fabric_choice.h"
#include "fabric_menu.h"
#include "fabrics_section.h"
#include "file_fields.h"
#include "fit_section.h"
#include "interactive_resolution.h"
#include "orbit_camera.h"
#include "preview_lights.h"
#include "preview_renderer.h"
#include "preview_window.h"
#include "render_section.h"
#include "rendered_viewport.h"
#include "scene_picker.h"
#include "status_line.h"
#include "undo_history.h"
#include "view_refinement.h"
#include "widget_map.h"
#include "woven_edits.h"

namespace woven {

// An output's default path: beside the scene, named after it (the procedural cloth's: `fallback`
// in the working directory).
std::string besideScene(const std::string& scene, const std::string& suffix, const std::string& fallback);

// What an undo restores: every edit, the edit the panel tunes, and the draft being edited.
struct MaterialState {
    std::vector<WovenEdit> edits;
    int editIndex = -1;
    DraftSection::State draft;
    std::optional<ChosenFabric> chosenFabric;
};

// What the view's progressive refinement depends on beyond the scene's generation: a frame of
// another view starts it anew.
struct RefinedView {
    glm::mat4 cameraToWorld{0.0f};
    float yfov = 0.0f;
    glm::ivec2 size{0};
    uint64_t sceneGeneration = 0;
    bool filterWeave = false, shadows = false;
    bool operator==(const RefinedView& o) const {
        return cameraToWorld == o.cameraToWorld && yfov == o.yfov && size == o.size &&
               sceneGeneration == o.sceneGeneration && filterWeave == o.filterWeave && shadows == o.shadows;
    }
};

class PreviewWindow {
public:
    // The label column of the panel: the widest label any of its fields shows.
    static float labelWidth();

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
    void drawWeaveControls(WovenParams& p);
    void drawThreadPalette(WovenParams& p);
    bool drawThreadsPerCm(WovenParams& p, const ParamInfo& repeat);
    void drawDraftControls(WovenParams& p);
    void drawFabricControls(WovenParams& p);
    // A material's draft ("wif") in the draft view of the edited material; none: that edit's
    // draft is closed, for it no longer describes the material.
    void showDraftOf(const std::string& wif, std::vector<std::string>& warnings);
    // The edited material's weave and thread colours as a draft (weave_draft.h) in the draft
    // view, for a fabric that has no draft file: its threads are edited as a draft's are. `show`:
    // the Draft window expanded (a scene's own starts collapsed).
    void showWeaveAsDraft(const WovenParams& p, const std::string& name, bool show);
    void drawDraftWindow();
    void applyEdits();
    // Any change of a material: the shown final frame is of the old cloth, and the change is
    // one undo step once no control is held (commitCompletedEdit(), at the end of each frame).
    void materialEdited();
    void commitCompletedEdit();
    MaterialState materialState() const;
    void restore(MaterialState state);
    void undo();
    void redo();
    // Ctrl+Z, Ctrl+Shift+Z (or Ctrl+Y), Ctrl+S: unless a text field takes the keys.
    void handleShortcuts();
    void drawUndoButtons();
    // A woven scene file at `path`: every edit, the view and the Render button's settings; Save
    // writes it there from then on. `startAnew` (Save As): the opened scene, not what the file held.
    void saveSceneFile(const std::string& path, bool startAnew);
    // The Render button's camera: the one a scene file saved now renders through.
    Camera renderCamera() const;
    void drawLightControls();
    // What the Render section renders and exports: the scene and cameras as the window shows them.
    RenderSection::Shown shown();
    // The finished fit's material into the edit it was started for, now the edited one.
    void applyFinishedFit();
    // The target of the edit the panel tunes; empty for none.
    std::string editedTarget() const;
    // The length per UV unit of the target's meshes, measured once a scene (nullopt: no UVs).
    const std::optional<glm::dvec2>& metresPerUvOf(const std::string& target);
    // Rendered mode (rendered_view.cpp).
    void setRenderedView(bool on);
    void handleViewKeys();
    bool restWhileRendering();
    void drawPreviewView(int width, int height, double now);
    void drawRenderedView();
    nlohmann::json renderedViewState() const;
    void writeWindowScreenshot(const std::string& path);
    void writeWidgetMap(const std::string& path);
    WovenParams* editedParams();
    SceneDescription& scene() { return edits_->sceneForLighting(); }

    bool busy() const;
    bool restUntilNeeded();
    static void wake(GLFWwindow* window);
    static void onScroll(GLFWwindow* window, double, double dy);
    static void onDrop(GLFWwindow* window, int count, const char** paths);
    // Between ImGui's GLFW backend and GLFW: a key released before ImGui saw it down (a quick
    // Tab or Enter while a frame takes 100 ms and more, in software) is released after the
    // next ImGui::NewFrame() instead, so ImGui sees it pressed. ImGui 1.86's backend keeps only
    // whether a key is down, not that it went down; it does so for mouse buttons alone.
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    void releaseDeferredKeys();
    void releaseDeferredModifiers();

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
    DisplayTransform display_;
    bool filterWeave_ = true;
    bool shadows_ = true;
    double scroll_ = 0.0;
    std::vector<std::string> droppedPaths_;
    GLFWkeyfun imguiKeyCallback_ = nullptr;
    std::vector<int> pressedSinceFrame_;       // keys that went down since the last NewFrame()
    std::vector<glm::ivec3> deferredReleases_;  // key, scancode, mods
    std::vector<glm::ivec3> deferredModifierReleases_;  // for the next frame, before NewFrame()
    glm::dvec2 lastCursor_{0.0};
    std::optional<glm::dvec2> pressedAt_;  // where the left button went down, while it is down
    bool steering_ = false;                // the camera is being dragged or zoomed
    InteractiveResolution resolution_;
    // Counts the changes of what the view shows (materials, lights, the scene): each starts the
    // view's refinement anew, as does another camera or size (refinedView_).
    uint64_t sceneGeneration_ = 0;
    RefinedView refinedView_;
    int refinement_ = 0;  // the frame of the running mean last rendered
    // With --widget-map, for the window tests to tell whether an edit changed the view: the first
    // full-size frame of the latest refinement (a view begun), its checksum and mean linear radiance.
    struct BegunView {
        int frame = -1;
        std::string checksum;
        glm::dvec3 mean{0.0};
    } begunView_;
    StatusLine status_;  // what the last action said, and the warnings since the scene was opened
    char materialPath_[512] = "material.json";  // Save As's and Load material's file
    std::string savePath_;  // Save's: beside the scene, until Save As chose another
    glm::vec3 loadedEnvironment_{0.0f};  // as opened: Save writes the colour once it was changed

    UndoHistory<MaterialState> history_;

    // Every edit in the draft view is applied to its edit's parameters at once, so the next frame
    // shows it.
    DraftSection draft_;

    FabricsSection fabrics_;

    FitSection fit_;

    RenderSection render_;

    // The view's Rendered mode: the path tracer's progressive frame in place of the GLSL one.
    RenderedViewport rendered_;
    bool renderedView_ = false;
    std::optional<Image> renderedImage_;  // the latest it drew
    DisplayTransform renderedDisplay_;    // the transform its texture was made with
    GLuint renderedTexture_ = 0;

    // The panel's widgets this frame: ID clashes warned on stderr, and for --widget-map.
    WidgetMap widgets_;
    int frame_ = 0;
    bool interacting_ = false;  // the last frame was drawn as an interactive one
    // A resting window draws nothing until an input (counted by the callbacks) or work arrives.
    uint64_t inputs_ = 0, inputsSeen_ = 0;
    uint64_t inputsDrawn_ = 0;  // inputs_ when the last frame began
    double lastInputAt_ = -1e9;  // glfwGetTime() of the last frame that began with new input
    double settleUntil_ = 0.0;
    int settleFrames_ = 0;
};

}  // namespace woven
