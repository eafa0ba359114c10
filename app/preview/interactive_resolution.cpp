#include "interactive_resolution.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <imgui.h>
#include <imgui_internal.h>

namespace woven {

bool panelInteracting() {
    const ImGuiContext* g = ImGui::GetCurrentContext();
    if (!g || g->ActiveId == 0) return false;
    // The text field that has the focus (a slider typed into after Ctrl+click is one too).
    return g->InputTextState.ID != g->ActiveId;
}

InteractiveResolution::InteractiveResolution(const Settings& settings) : settings_(settings) {}

glm::ivec2 InteractiveResolution::frameSize(glm::ivec2 full, bool interacting, double now) {
    if (interacting) lastInteraction_ = now;
    interactive_ = now - lastInteraction_ < settings_.settleSeconds;
    sized_ = true;
    // Before any frame was timed, half size: a quarter of the pixels.
    scale_ = !interactive_ ? 1.0f : interactiveScale_ > 0.0f ? interactiveScale_ : 0.5f;
    return glm::max(glm::ivec2(glm::round(glm::vec2(full) * scale_)), glm::ivec2(1));
}

void InteractiveResolution::frameTook(double seconds) {
    if (!sized_ || !(seconds > 0.0)) return;
    sized_ = false;
    // A frame's time is mostly proportional to its pixels, so to the square of the scale.
    const float ideal = scale_ * float(std::sqrt(settings_.targetSeconds / seconds));
    if (!interactive_) {
        // A full frame tells the first interactive scale; after that, the interactive frames'
        // own times, which include what does not scale with the pixels, know better.
        if (interactiveScale_ == 0.0f) interactiveScale_ = std::clamp(ideal, settings_.minScale, 1.0f);
        return;
    }
    // Near the target (from 17 % under it to 11 % over) it stays, so that the frame size does not
    // flicker with every hiccup of a loaded machine; beyond, it at most halves or grows by a fifth
    // per frame.
    const float ratio = ideal / scale_;
    if (ratio < 0.95f || ratio > 1.1f)
        interactiveScale_ = std::clamp(scale_ * std::clamp(ratio, 0.5f, 1.2f), settings_.minScale, 1.0f);
}

}  // namespace woven
