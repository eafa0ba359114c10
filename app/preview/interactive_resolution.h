#pragma once
// The size the preview renders each frame at, so that it stays interactive where the GPU is slow
// or absent (llvmpipe): while the camera or a slider moves, at a reduced scale of the window,
// chosen from the measured frame times to hold a target frame rate; at the window's full size
// once the interaction has ended, for full quality when idle. The window asks frameSize() before
// each frame and reports the frame's time with frameTook(); it shows the reduced frame scaled up
// (PreviewRenderer::display), so the look, exposure and tone curve stay those of the full frame.
#include <glm/vec2.hpp>

namespace woven {

// Whether the window's ImGui panel is being interacted with, in the current ImGui context: a
// slider, drag, colour or button held with the mouse or keys. A text field with the keyboard
// focus is not (ImGui counts it as active as long as it has the focus, which would keep the view
// at its interactive resolution while one types, and after): typing changes no value while it
// goes on the way a drag does.
bool panelInteracting();

class InteractiveResolution {
public:
    struct Settings {
        double targetSeconds = 1.0 / 24.0;  // per interactive frame: 24 fps leaves a margin over 20
        double settleSeconds = 0.25;        // after the last interaction, still interactive (a wheel's clicks)
        // Of the window's width and height. As low as Blender's viewport goes (pixel size 8): on
        // llvmpipe the weave's far-field filter makes a pixel dearer the smaller the frame.
        float minScale = 0.125f;
    };

    InteractiveResolution() : InteractiveResolution(Settings{}) {}
    explicit InteractiveResolution(const Settings& settings);

    // The size to render the next frame at, for a window of `full` pixels: `full` when idle,
    // smaller while `interacting` (the camera or a value being dragged) or shortly after.
    // `now`: seconds on any steady clock.
    glm::ivec2 frameSize(glm::ivec2 full, bool interacting, double now);
    // The wall time the frame that frameSize() last sized took, from the start of one frame to
    // the start of the next: what the user sees. Ignored when no frame was sized since the last
    // call (the window showed something else, such as the rendered frame).
    void frameTook(double seconds);

    float scale() const { return scale_; }  // of the frame frameSize() last sized

private:
    Settings settings_;
    float scale_ = 1.0f;             // of the last frame sized
    bool interactive_ = false;       // whether that frame was an interactive one
    bool sized_ = false;             // frameSize() was called since the last frameTook()
    float interactiveScale_ = 0.0f;  // of the next interactive frame; 0: not known yet
    double lastInteraction_ = -1e300;
};

}  // namespace woven
