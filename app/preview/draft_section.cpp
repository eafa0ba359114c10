#include "draft_section.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

#include "file_fields.h"

namespace woven {

void DraftSection::open(DraftEditor editor, int edit, bool show, const std::string& path) {
    setPath(path.empty() ? editor.name() : path);
    state_ = {std::move(editor), edit};
    show_ = show;
}

void DraftSection::closeFor(int edit) {
    if (state_.edit == edit) state_.editor.reset();
}

void DraftSection::restore(State state) {
    state_ = std::move(state);
    if (state_.editor) setPath(state_.editor->name());
}

void DraftSection::setPath(const std::string& path) { copyToBuffer(path_, path); }

bool DraftSection::drawWindow(WovenParams& woven, StatusLine& status) {
    if (!state_.editor) return false;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Beside the panel, as wide as it leaves the window.
    const ImGuiWindow* panel = ImGui::FindWindowByName("woven");
    const float left = panel ? panel->Rect().Max.x + 8.0f : 456.0f;
    ImGui::SetNextWindowPos(ImVec2(left, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(display.x - left - 8.0f, 200.0f), display.y * 0.45f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(!show_, show_ ? ImGuiCond_Always : ImGuiCond_FirstUseEver);
    show_ = false;
    ImGui::Begin("Draft");
    bool changed = false;
    status.attempt([&] {
        if (view_.draw(*state_.editor, woven.warp_color, woven.weft_color)) {
            woven = state_.editor->material(woven);
            changed = true;
        }
    });
    ImGui::End();
    return changed;
}

}  // namespace woven
