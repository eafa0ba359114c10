#pragma once
// An ImGui context with no window and no renderer, driven frame by frame with a mouse the test
// moves: for the panel logic that reads ImGui's state (no backend, no GL).
#include <imgui.h>

namespace woven {

class HeadlessImGui {
public:
    HeadlessImGui() : context_(ImGui::CreateContext()) {
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(800, 600);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // builds the font atlas
    }
    ~HeadlessImGui() { ImGui::DestroyContext(context_); }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;

    // One frame: the mouse at `mouse`, its left button `down`; `draw` submits the widgets.
    template <typename F>
    void frame(ImVec2 mouse, bool down, F draw) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0, 0));
        ImGui::SetNextWindowSize(ImVec2(400, 300));
        ImGui::Begin("panel");
        draw();
        ImGui::End();
        ImGui::Render();
    }

private:
    ImGuiContext* context_;
};

inline ImVec2 itemCentre() {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    return ImVec2((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
}

}  // namespace woven
