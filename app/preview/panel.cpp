// The window's ImGui panel: the view's settings, then its sections (each in an ID scope of its
// own, so one label in two sections is two widgets), and the Lights section.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>

#include "preview_window_impl.h"
#include "scene_camera.h"
#include "studio_environments.h"
#include "woven_params.h"

namespace woven {

namespace {

// The fields' width the panel is sized for, beside the label column.
constexpr float kFieldWidth = 180.0f;

}  // namespace

float PreviewWindow::labelWidth() {
    // Every label the panel puts beside a field (checkboxes and buttons size themselves).
    static const char* const labels[] = {"exposure",   "tone map",        "target",     "woven",    "fabric",  "weave preset",
                                         "scene file", "draft file",      "render size", "spp",     "noise threshold",
                                         "integrator", "image file",      "intensity",  "position", "direction",
                                         "environment", "shot files",    "swatch",     "fit seconds", "rotation",
                                         "brightness", "studio light"};
    float width = 0.0f;
    for (const char* label : labels) width = std::max(width, ImGui::CalcTextSize(label, nullptr, true).x);
    for (const ParamInfo& info : wovenParamTable())
        if (isNumeric(info.type)) width = std::max(width, ImGui::CalcTextSize(info.label, nullptr, true).x);
    return width;
}

// Edits the scene's own lights, so the Render button sees the same lighting as the preview.
void PreviewWindow::drawLightControls() {
    static const char* typeNames[] = {"point", "spot", "directional"};
    bool changed = false;
    for (size_t i = 0; i < scene().lights.size(); ++i) {
        PunctualLight& light = scene().lights[i];
        ImGui::PushID(int(i));
        ImGui::Text("light %zu (%s)", i, typeNames[int(light.type)]);
        changed |= ui::ColorEdit3("intensity", &light.intensity.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        if (light.type == PunctualLight::Type::Point)
            changed |= ui::DragFloat3("position", &light.position.x, 0.05f);
        if (light.type != PunctualLight::Type::Point && ui::SliderFloat3("direction", &light.direction.x, -1.0f, 1.0f)) {
            if (glm::length(light.direction) < 1e-3f) light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
            light.direction = glm::normalize(light.direction);
            changed = true;
        }
        ImGui::PopID();
    }
    changed |= ui::ColorEdit3("environment", &scene().environment.color.x,
                              ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    // Look development: one of the environments woven generates (keeping the rotation), the
    // environment turned about +y, and brightened keeping its tint (the scene file's
    // environment.rotation and environment.intensity).
    Environment& env = scene().environment;
    if (ui::BeginCombo("studio light", "(choose)")) {
        for (const StudioEnvironment& studio : studioEnvironments())
            if (ui::Selectable(studio.name, false)) {
                const float rotation = env.rotation;
                env = studio.make();
                env.rotation = rotation;
                changed = true;
                status_.say(std::string("lit by the ") + studio.name + " environment: " + studio.description);
            }
        ui::EndCombo();
    }
    float degrees = std::remainder(glm::degrees(env.rotation), 360.0f);
    if (ui::SliderFloat("rotation", &degrees, -180.0f, 180.0f, "%.0f degrees")) {
        env.rotation = glm::radians(degrees);
        changed = true;
    }
    const float before = std::max({env.color.r, env.color.g, env.color.b});
    float brightness = before;
    if (ui::SliderFloat("brightness", &brightness, 0.0f, 16.0f, "%.3f", ImGuiSliderFlags_Logarithmic)) {
        env.color = before > 0.0f ? env.color * (brightness / before) : glm::vec3(brightness);
        changed = true;
    }
    if (changed) {
        lights_ = PreviewLights::fromScene(scene());
        ++sceneGeneration_;
    }
}

void PreviewWindow::drawPanel() {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float labels = labelWidth() + style.ItemInnerSpacing.x;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // At most 35 % of the window, so that the cloth keeps the view, unless the fields would then
    // be narrower than half their width; never wider than the window.
    const float chrome = labels + 2.0f * style.WindowPadding.x + style.ScrollbarSize;
    const float width = std::min({kFieldWidth + chrome, std::max(0.35f * display.x - 8.0f, 0.5f * kFieldWidth + chrome),
                                  std::max(display.x - 16.0f, 100.0f)});
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width, display.y - 16), ImGuiCond_FirstUseEver);
    // Never larger than the window, which may shrink: every control is reached by scrolling.
    ImGui::SetNextWindowSizeConstraints(ImVec2(100, 100), ImVec2(std::max(display.x - 16, 100.0f), std::max(display.y - 16, 100.0f)));
    ImGui::Begin("woven");
    // Fields end where the longest label still fits before the panel's edge, however wide it is.
    ImGui::PushItemWidth(-labels);
    ImGui::Text("%s", scenePath_.empty() ? "procedural cloth" : scenePath_.c_str());
    if (renderedView_) ImGui::TextWrapped("%s", rendered_.statusText().c_str());
    else
        ImGui::Text("%.1f ms/frame, drawn at %.0f%%", 1000.0f / std::max(ImGui::GetIO().Framerate, 1e-3f),
                    100.0f * resolution_.scale());
    static const char* const toneMaps[] = {"clamp", "reinhard", "aces"};  // core's ToneMap order
    int toneMap = int(display_.toneMap);
    const bool exposureChanged = ui::SliderFloat("exposure", &display_.exposure, -8.0f, 8.0f, "%.2f stops");
    const bool toneMapChanged = ui::Combo("tone map", &toneMap, toneMaps, int(std::size(toneMaps)));
    display_.toneMap = ToneMap(toneMap);
    if (exposureChanged || toneMapChanged) render_.redisplay(display_);
    ui::Checkbox("filter distant weave", &filterWeave_);
    ImGui::SameLine();
    ui::Checkbox("shadows", &shadows_);
    bool rendered = renderedView_;
    if (ui::Checkbox("rendered view (R)", &rendered)) setRenderedView(rendered);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the path tracer's progressive frame in place of the OpenGL preview");
    if (ui::Button("Frame scene")) {
        const SceneBox box = sceneBounds(scene());
        camera_ = OrbitCamera::around(framingCamera(box, camera_.camera().yfov), box);
    }
    status_.draw();

    // Render first, and Lights (closed) before the long Material section: both within the
    // window's height without scrolling.
    if (ui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushID("render");
        render_.draw(shown(), display_, status_);
        ImGui::PopID();
    }
    if (ui::CollapsingHeader("Lights")) {
        ImGui::PushID("lights");
        drawLightControls();
        ImGui::PopID();
    }
    if (ui::CollapsingHeader("Fit")) {
        ImGui::PushID("fit");
        fit_.draw(editedTarget(), status_);
        ImGui::PopID();
    }
    applyFinishedFit();
    if (ui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushID("selection");
        drawSelection();
        ImGui::PopID();
    }
    if (ui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::PushID("material");
        const auto& edits = edits_->edits();
        if (ui::BeginCombo("woven", editIndex_ >= 0 ? edits[size_t(editIndex_)].target.c_str() : "(none: click a surface)")) {
            for (size_t i = 0; i < edits.size(); ++i)
                if (ui::Selectable(edits[i].target.c_str(), int(i) == editIndex_)) editIndex_ = int(i);
            ui::EndCombo();
        }
        drawUndoButtons();
        if (WovenParams* p = editedParams()) {
            const size_t changesBefore = widgets_.valueChanges();
            drawMaterialControls(*p);
            // The rendered frame is of the old cloth: any edit goes back to the live preview.
            if (widgets_.valueChanges() != changesBefore) materialEdited();
            applyEdits();
        }
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace woven
