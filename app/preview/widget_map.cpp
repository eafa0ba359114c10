#include "widget_map.h"

#include <imgui_internal.h>

#include <algorithm>
#include <iostream>
#include <map>

namespace woven {

namespace {

WidgetMap* current = nullptr;

nlohmann::json point(ImVec2 p) { return {p.x, p.y}; }
nlohmann::json rect(ImVec2 lo, ImVec2 hi) { return {lo.x, lo.y, hi.x, hi.y}; }

// Records the widget just drawn and passes its result on.
bool recorded(bool result, const char* label, const char* kind) {
    if (current) {
        current->record(label, kind);
        if (result) current->noteChange(kind);
    }
    return result;
}

}  // namespace

void setCurrentWidgetMap(WidgetMap* map) { current = map; }

void WidgetMap::noteChange(const char* kind) {
    // Buttons act; the others hold a value (a checkbox, a switch of the material or of the view).
    static const std::set<std::string> values = {"slider", "drag", "colour", "input", "selectable", "checkbox"};
    if (values.count(kind)) ++valueChanges_;
}

void WidgetMap::beginFrame() {
    items_.clear();
    windows_ = nlohmann::json::object();
}

void WidgetMap::record(const char* label, const char* kind) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    WidgetItem item;
    item.label = label;
    item.kind = kind;
    item.window = window->Name;
    // What the widget hashed its label into: for a group (a multi-component slider, a field with
    // step buttons, a colour editor) the seed of its parts' IDs, so one label twice clashes too.
    item.id = ImGui::GetID(label);
    item.min = g.LastItemData.Rect.Min;
    item.max = g.LastItemData.Rect.Max;
    // A field's frame is its navigation rectangle; a group's is the group.
    const bool group = g.LastItemData.ID == 0;
    item.frameMin = group ? item.min : g.LastItemData.NavRect.Min;
    item.frameMax = group ? item.max : g.LastItemData.NavRect.Max;
    // A group's fields end where the item width does, before its label.
    if (group) item.frameMax.x = std::min(item.max.x, item.min.x + ImGui::CalcItemWidth());
    item.visible = ImGui::IsItemVisible();
    item.disabled = (g.CurrentItemFlags & ImGuiItemFlags_Disabled) != 0;
    items_.push_back(std::move(item));
    if (!windows_.contains(window->Name))
        windows_[window->Name] = {{"pos", point(window->Pos)},
                                  {"size", point(window->Size)},
                                  {"clip", rect(window->InnerClipRect.Min, window->InnerClipRect.Max)},
                                  {"scroll", point(window->Scroll)},
                                  {"scroll_max", point(window->ScrollMax)}};
}

std::vector<WidgetClash> WidgetMap::clashes() const {
    std::map<uint32_t, std::vector<size_t>> byId;
    for (size_t i = 0; i < items_.size(); ++i) byId[items_[i].id].push_back(i);
    std::vector<WidgetClash> out;
    for (auto& [id, indices] : byId)
        if (indices.size() > 1) out.push_back({id, indices});
    return out;
}

void WidgetMap::warnClashes() {
    for (const WidgetClash& clash : clashes()) {
        std::string labels;
        for (size_t i : clash.items)
            labels += (labels.empty() ? "" : ", ") + items_[i].kind + " \"" + items_[i].label + "\" in \"" +
                      items_[i].window + "\"";
        if (!warned_.insert(labels).second) continue;
        std::cerr << "warning: ImGui ID clash (one ID, the first takes the other's clicks): " << labels << "\n";
    }
}

nlohmann::json WidgetMap::json() const {
    nlohmann::json items = nlohmann::json::array();
    for (const WidgetItem& item : items_)
        items.push_back({{"label", item.label},
                         {"kind", item.kind},
                         {"window", item.window},
                         {"id", item.id},
                         {"rect", rect(item.min, item.max)},
                         {"frame", rect(item.frameMin, item.frameMax)},
                         {"visible", item.visible},
                         {"disabled", item.disabled}});
    nlohmann::json clashList = nlohmann::json::array();
    for (const WidgetClash& clash : clashes()) {
        nlohmann::json labels = nlohmann::json::array();
        for (size_t i : clash.items) labels.push_back(items_[i].label);
        clashList.push_back({{"id", clash.id}, {"labels", labels}});
    }
    return {{"items", items}, {"clashes", clashList}, {"windows", windows_}};
}

namespace ui {

bool Button(const char* label, const ImVec2& size) { return recorded(ImGui::Button(label, size), label, "button"); }
bool Checkbox(const char* label, bool* v) { return recorded(ImGui::Checkbox(label, v), label, "checkbox"); }
bool CollapsingHeader(const char* label, ImGuiTreeNodeFlags flags) {
    return recorded(ImGui::CollapsingHeader(label, flags), label, "header");
}
bool BeginCombo(const char* label, const char* preview) {
    const bool open = ImGui::BeginCombo(label, preview);
    // An open combo's popup is the current window now: its box is recorded by EndCombo, in its
    // parent's ID stack again, which End() gives the box back as the last item.
    if (current) {
        if (open) current->pendingCombos_.push_back(label);
        else current->record(label, "combo");
    }
    return open;
}
void EndCombo() {
    ImGui::EndCombo();
    if (current && !current->pendingCombos_.empty()) {
        current->record(current->pendingCombos_.back().c_str(), "combo");
        current->pendingCombos_.pop_back();
    }
}
bool Selectable(const char* label, bool selected, ImGuiSelectableFlags flags, const ImVec2& size) {
    return recorded(ImGui::Selectable(label, selected, flags, size), label, "selectable");
}
bool Combo(const char* label, int* current, const char* const items[], int count) {
    return recorded(ImGui::Combo(label, current, items, count), label, "combo");
}
bool SliderFloat(const char* label, float* v, float min, float max, const char* format, ImGuiSliderFlags flags) {
    return recorded(ImGui::SliderFloat(label, v, min, max, format, flags), label, "slider");
}
bool SliderFloat2(const char* label, float v[2], float min, float max, const char* format, ImGuiSliderFlags flags) {
    return recorded(ImGui::SliderFloat2(label, v, min, max, format, flags), label, "slider");
}
bool SliderFloat3(const char* label, float v[3], float min, float max) {
    return recorded(ImGui::SliderFloat3(label, v, min, max), label, "slider");
}
bool SliderInt(const char* label, int* v, int min, int max) {
    return recorded(ImGui::SliderInt(label, v, min, max), label, "slider");
}
bool DragFloat(const char* label, float* v, float speed, float min, float max, const char* format, ImGuiSliderFlags flags) {
    return recorded(ImGui::DragFloat(label, v, speed, min, max, format, flags), label, "drag");
}
bool DragFloat2(const char* label, float v[2], float speed, float min, float max, const char* format,
                ImGuiSliderFlags flags) {
    return recorded(ImGui::DragFloat2(label, v, speed, min, max, format, flags), label, "drag");
}
bool DragFloat3(const char* label, float v[3], float speed) {
    return recorded(ImGui::DragFloat3(label, v, speed), label, "drag");
}
bool ColorEdit3(const char* label, float col[3], ImGuiColorEditFlags flags) {
    return recorded(ImGui::ColorEdit3(label, col, flags), label, "colour");
}
bool InputInt(const char* label, int* v, int step, int stepFast, ImGuiInputTextFlags flags) {
    return recorded(ImGui::InputInt(label, v, step, stepFast, flags), label, "input");
}
bool InputInt3(const char* label, int v[3]) { return recorded(ImGui::InputInt3(label, v), label, "input"); }
bool InputDouble(const char* label, double* v, double step, double stepFast, const char* format) {
    return recorded(ImGui::InputDouble(label, v, step, stepFast, format), label, "input");
}
bool InputText(const char* label, char* buffer, size_t size) {
    // Every text field names a file or a target for a button beside it (Save As, Load, Export,
    // Fit): typing in it changes no value, so it is no edit of the cloth and no undo step.
    const bool typed = ImGui::InputText(label, buffer, size);
    recorded(false, label, "input");
    return typed;
}

}  // namespace ui

}  // namespace woven
