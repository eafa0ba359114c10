// The window's undo and redo of material edits, its keyboard shortcuts, and Save: the edits as a
// woven scene file that `woven render` renders as the Render button does.
#include <imgui.h>

#include "material_file.h"
#include "preview_window_impl.h"
#include "sampler.h"

namespace woven {

void PreviewWindow::materialEdited() {
    render_.hide();  // the rendered frame is of the old cloth
    history_.edited();
    ++sceneGeneration_;
}

// A drag is one step, not one a frame: the step is taken once the control is let go.
void PreviewWindow::commitCompletedEdit() {
    if (history_.pending() && !ImGui::IsAnyItemActive()) history_.complete(materialState());
}

MaterialState PreviewWindow::materialState() const {
    return {edits_->edits(), editIndex_, draft_.state(), fabrics_.chosen()};
}

void PreviewWindow::restore(MaterialState state) {
    edits_->restore(std::move(state.edits));
    editIndex_ = state.editIndex;
    draft_.restore(std::move(state.draft));
    fabrics_.setChosen(std::move(state.chosenFabric));
    render_.hide();
    ++sceneGeneration_;
    applyEdits();
}

void PreviewWindow::undo() {
    commitCompletedEdit();
    if (std::optional<MaterialState> before = history_.undo(materialState())) {
        restore(std::move(*before));
        status_.say("undone");
    } else {
        status_.say("nothing to undo");
    }
}

void PreviewWindow::redo() {
    if (std::optional<MaterialState> after = history_.redo(materialState())) {
        restore(std::move(*after));
        status_.say("redone");
    } else {
        status_.say("nothing to redo");
    }
}

void PreviewWindow::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.KeyCtrl || io.WantTextInput) return;  // a text field has its own undo
    if (ImGui::IsKeyPressed(GLFW_KEY_Z, false)) io.KeyShift ? redo() : undo();
    else if (ImGui::IsKeyPressed(GLFW_KEY_Y, false)) redo();
    else if (ImGui::IsKeyPressed(GLFW_KEY_S, false) && editedParams()) status_.attempt([&] { saveSceneFile(savePath_, false); });
}

void PreviewWindow::drawUndoButtons() {
    ImGui::BeginDisabled(!history_.canUndo());
    if (ui::Button("Undo")) undo();
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Ctrl+Z: the last material edit");
    ImGui::SameLine();
    ImGui::BeginDisabled(!history_.canRedo());
    if (ui::Button("Redo")) redo();
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Ctrl+Shift+Z or Ctrl+Y");
}

void PreviewWindow::saveSceneFile(const std::string& path, bool startAnew) {
    SceneSave save;
    for (const WovenEdit& e : edits_->edits()) save.materials.emplace_back(e.target, e.params);
    if (camera_.moved()) save.camera = viewOf(camera_.camera());
    const RenderSettings& render = render_.settings();
    save.render = {render.width, render.height, render.spp, render.integrator, samplerName(render.sampler),
                   render.noiseThreshold};
    if (scene().environment.color != loadedEnvironment_) save.environmentColor = scene().environment.color;
    save.inputs = scene().inputFiles;
    save.startAnew = startAnew;
    saveScene(path, scenePath_, save);
    savePath_ = path;
    status_.say("saved " + path);
}

// Unmoved, the scene's own camera, which the saved file keeps; moved, the view the file is given.
Camera PreviewWindow::renderCamera() const {
    return camera_.moved() ? cameraOf(viewOf(camera_.camera())) : camera_.camera();
}

RenderSection::Shown PreviewWindow::shown() {
    std::string material;  // the edited cloth's, for a U3M export
    if (editIndex_ >= 0) {
        const int m = edits_->materialOf(edits_->edits()[size_t(editIndex_)].target);
        if (m >= 0) material = scene().materials[size_t(m)].name;
    }
    return {scene(), renderCamera(), camera_.camera(), material, options_.frame.denoise};
}

}  // namespace woven
