#pragma once
// What the previewer's ImGui panel drew in one frame: each widget's label, ImGui ID, rectangle and
// window, recorded by the thin ui:: wrappers below after each widget. ImGui 1.86 (Debian's, with
// no test-engine hooks) does not notice two widgets of one ID, which then act as one (a click on
// the second goes to the first): WidgetMap reports such clashes, and writes the frame as JSON for
// the window test (`woven preview --widget-map FILE`), which finds the widgets it clicks there.
#include <imgui.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "image.h"

namespace woven {

struct WidgetItem {
    std::string label;   // as passed to ImGui, "##" suffix included
    std::string kind;    // "button", "slider", "input", "header", ...
    std::string window;  // the ImGui window it was drawn in
    uint32_t id = 0;     // the ID its label makes in the ID stack it was drawn in
    ImVec2 min, max;     // the whole item, label included (ImGui::GetItemRectMin/Max)
    ImVec2 frameMin, frameMax;  // the part that takes a click (a field's frame, a group's fields, without the label)
    bool visible = false;       // not clipped away (scrolled out, a collapsed window)
    bool disabled = false;      // drawn disabled (ImGui::BeginDisabled): it takes no input
};

// The mean of every pixel, summed in double (an empty image: 0): how the widget map says what a
// view or a frame shows.
inline glm::dvec3 meanColour(const Image& image) {
    glm::dvec3 sum(0.0);
    for (const glm::vec3& c : image.pixels) sum += glm::dvec3(c);
    return image.pixels.empty() ? sum : sum / double(image.pixels.size());
}

namespace ui {
bool BeginCombo(const char* label, const char* preview);
void EndCombo();
}  // namespace ui

struct WidgetClash {
    uint32_t id = 0;
    std::vector<size_t> items;  // indices into WidgetMap::items(), two or more
};

class WidgetMap {
public:
    // Forgets the last frame's widgets.
    void beginFrame();
    // Right after a widget, in the ID stack it was drawn in.
    void record(const char* label, const char* kind);

    // A widget returned true ("changed" for a value, "pressed" for a button).
    void noteChange(const char* kind);
    // How many value widgets (sliders, drags, colours, fields, selectables, checkboxes) changed a value so far:
    // the difference across a section says whether the user edited anything in it.
    size_t valueChanges() const { return valueChanges_; }

    const std::vector<WidgetItem>& items() const { return items_; }
    std::vector<WidgetClash> clashes() const;
    // One line on stderr for each clash not reported before ("warning: ImGui ID clash ...").
    void warnClashes();

    // {"items": [...], "clashes": [...], "windows": {name: {"pos", "size", "clip"}}}
    nlohmann::json json() const;

private:
    std::vector<WidgetItem> items_;
    nlohmann::json windows_ = nlohmann::json::object();
    std::set<std::string> warned_;  // the clashes already said, by their labels
    size_t valueChanges_ = 0;
    std::vector<std::string> pendingCombos_;  // open combos' labels, recorded at EndCombo
    friend bool ui::BeginCombo(const char*, const char*);
    friend void ui::EndCombo();
};

// The map the ui:: wrappers feed; null: they only draw.
void setCurrentWidgetMap(WidgetMap* map);

// ImGui's widgets, each recorded in the current WidgetMap.
namespace ui {
bool Button(const char* label, const ImVec2& size = ImVec2(0, 0));
bool Checkbox(const char* label, bool* v);
bool CollapsingHeader(const char* label, ImGuiTreeNodeFlags flags = 0);
bool BeginCombo(const char* label, const char* preview);  // then ui::EndCombo() when it returned true
void EndCombo();
bool Selectable(const char* label, bool selected, ImGuiSelectableFlags flags = 0, const ImVec2& size = ImVec2(0, 0));
bool Combo(const char* label, int* current, const char* const items[], int count);
bool SliderFloat(const char* label, float* v, float min, float max, const char* format = "%.3f",
                 ImGuiSliderFlags flags = 0);
bool SliderFloat2(const char* label, float v[2], float min, float max, const char* format = "%.3f",
                  ImGuiSliderFlags flags = 0);
bool SliderFloat3(const char* label, float v[3], float min, float max);
bool SliderInt(const char* label, int* v, int min, int max);
bool DragFloat(const char* label, float* v, float speed, float min, float max, const char* format,
               ImGuiSliderFlags flags = 0);
bool DragFloat2(const char* label, float v[2], float speed, float min, float max, const char* format,
                ImGuiSliderFlags flags = 0);
bool DragFloat3(const char* label, float v[3], float speed);
bool ColorEdit3(const char* label, float col[3], ImGuiColorEditFlags flags = 0);
bool InputInt(const char* label, int* v, int step = 1, int stepFast = 100, ImGuiInputTextFlags flags = 0);
bool InputInt3(const char* label, int v[3]);
bool InputDouble(const char* label, double* v, double step, double stepFast, const char* format);
bool InputText(const char* label, char* buffer, size_t size);
}  // namespace ui

}  // namespace woven
