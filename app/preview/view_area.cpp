#include "view_area.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cstdint>

namespace woven {

ImVec4 viewArea() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImGuiWindow* panel = ImGui::FindWindowByName("woven");
    float left = 0.0f;
    if (panel && !panel->Collapsed && panel->Pos.x < display.x * 0.5f) left = std::min(panel->Rect().Max.x, display.x * 0.5f);
    return ImVec4(left, 0.0f, display.x, display.y);
}

void drawInView(GLuint texture, float imageAspect) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImVec4 area = viewArea();
    const ImVec2 free(area.z - area.x, area.w - area.y);
    ImVec2 size(free.x, free.x / imageAspect);
    if (size.y > free.y) size = ImVec2(free.y * imageAspect, free.y);
    const ImVec2 lo(area.x + (free.x - size.x) * 0.5f, area.y + (free.y - size.y) * 0.5f);
    draw->AddRectFilled(ImVec2(0, 0), display, IM_COL32(0, 0, 0, 255));
    draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), lo, ImVec2(lo.x + size.x, lo.y + size.y));
}

}  // namespace woven
