// The preview's frame size while interacting, driven by frame times from a model of a software
// renderer (time = fixed + per-pixel cost x pixels), so the controller is tested without a clock.
#include <gtest/gtest.h>

#include <vector>

#include "headless_imgui.h"
#include "interactive_resolution.h"

namespace woven {
namespace {

const glm::ivec2 kWindow(1280, 720);

// llvmpipe on two cores as bench_preview measured it: 310 ms for a full 1280x720 frame, of which
// about 10 ms do not depend on the frame's size.
struct SoftwareRenderer {
    double fixedSeconds = 0.010, fullFrameSeconds = 0.310;
    double seconds(glm::ivec2 size) const {
        return fixedSeconds + (fullFrameSeconds - fixedSeconds) * double(size.x) * size.y / (double(kWindow.x) * kWindow.y);
    }
};

// Runs `frames` frames, each taking the model's time for the size the controller gives, the
// clock `now` advancing by it; returns the last frame's size. `interacting(frame)` says whether
// the user steers during that frame.
template <typename F>
glm::ivec2 runFrames(InteractiveResolution& r, const SoftwareRenderer& gpu, double* now, int frames, F interacting,
                     std::vector<double>* times = nullptr) {
    glm::ivec2 size(0);
    for (int i = 0; i < frames; ++i) {
        size = r.frameSize(kWindow, interacting(i), *now);
        const double t = gpu.seconds(size);
        r.frameTook(t);
        *now += t;
        if (times) times->push_back(t);
    }
    return size;
}

TEST(InteractiveResolution, IdleFramesAreFullSize) {
    InteractiveResolution r;
    double now = 0.0;
    EXPECT_EQ(runFrames(r, SoftwareRenderer{}, &now, 5, [](int) { return false; }), kWindow);
    EXPECT_EQ(r.scale(), 1.0f);
}

TEST(InteractiveResolution, DraggingOnASlowRendererHoldsTheTargetFrameRateWithoutFlicker) {
    InteractiveResolution r;
    const SoftwareRenderer gpu;
    double now = 0.0;
    runFrames(r, gpu, &now, 3, [](int) { return false; });
    std::vector<double> times;
    runFrames(r, gpu, &now, 60, [](int) { return true; }, &times);
    // The first interactive frame is sized from the full frame's time alone: already within
    // reach of 20 fps (the fixed 10 ms makes it a little slow), and the controller settles
    // within a few frames.
    EXPECT_LT(times.front(), 1.0 / 15.0);
    for (size_t i = 5; i < times.size(); ++i) EXPECT_LE(times[i], 1.0 / 20.0) << "frame " << i;
    // Settled: the same size for the last 50 frames (a changing size would re-allocate the
    // target and make the picture swim).
    const float settled = r.scale();
    for (int i = 0; i < 50; ++i) {
        r.frameSize(kWindow, true, now);
        r.frameTook(gpu.seconds(glm::ivec2(glm::vec2(kWindow) * settled)));
        EXPECT_EQ(r.scale(), settled);
    }
    // And not much smaller than it needs to be: the settled frame uses at least 80 % of the
    // 24 fps target.
    EXPECT_GE(gpu.seconds(glm::ivec2(glm::vec2(kWindow) * settled)), 0.8 / 24.0);
}

TEST(InteractiveResolution, FullSizeOnceTheInteractionHasSettled) {
    InteractiveResolution r;
    const SoftwareRenderer gpu;
    double now = 0.0;
    runFrames(r, gpu, &now, 20, [](int) { return true; });
    ASSERT_LT(r.scale(), 0.5f);
    // A wheel's clicks come a few frames apart: still interactive between them.
    const double released = now;
    EXPECT_NE(r.frameSize(kWindow, false, released + 0.1), kWindow);
    EXPECT_EQ(r.frameSize(kWindow, false, released + 0.3), kWindow);
}

TEST(InteractiveResolution, AFastGpuKeepsFullSizeWhileInteracting) {
    InteractiveResolution r;
    SoftwareRenderer gpu;
    gpu.fixedSeconds = 0.001;
    gpu.fullFrameSeconds = 0.008;
    double now = 0.0;
    runFrames(r, gpu, &now, 2, [](int) { return false; });
    EXPECT_EQ(runFrames(r, gpu, &now, 30, [](int) { return true; }), kWindow);
}

TEST(InteractiveResolution, NeverSmallerThanTheFloor) {
    InteractiveResolution r;
    SoftwareRenderer gpu;
    gpu.fixedSeconds = 0.2;  // more than the whole target: no size can meet it
    gpu.fullFrameSeconds = 0.5;
    double now = 0.0;
    const glm::ivec2 size = runFrames(r, gpu, &now, 30, [](int) { return true; });
    EXPECT_EQ(size, glm::ivec2(160, 90));
}

TEST(InteractiveResolution, FramesItDidNotSizeDoNotCount) {
    InteractiveResolution r;
    const SoftwareRenderer gpu;
    double now = 0.0;
    runFrames(r, gpu, &now, 20, [](int) { return true; });
    const float settled = r.scale();
    // The window showed the rendered frame for a while: quick frames that drew no preview.
    for (int i = 0; i < 10; ++i) r.frameTook(0.001);
    r.frameSize(kWindow, true, now);
    EXPECT_EQ(r.scale(), settled);
}

}  // namespace
}  // namespace woven

// panelInteracting(), which the window asks each frame, on a real ImGui context: a text field
// with the keyboard focus is active to ImGui (IsAnyItemActive) but is no interaction; a slider
// held is.
namespace woven {
namespace {

struct Panel {
    char text[32] = "160";
    float value = 0.5f;
    ImVec2 textAt, sliderAt;  // the widgets' centres, as last drawn
    void draw() {
        ImGui::InputText("text", text, sizeof text);
        textAt = itemCentre();
        ImGui::SliderFloat("value", &value, 0.0f, 1.0f);
        sliderAt = itemCentre();
    }
};

TEST(PanelInteracting, NotWithoutAContextOrAnActiveItem) {
    EXPECT_FALSE(panelInteracting());
    HeadlessImGui imgui;
    Panel panel;
    for (int i = 0; i < 3; ++i) imgui.frame(ImVec2(390, 290), false, [&] { panel.draw(); });
    EXPECT_FALSE(ImGui::IsAnyItemActive());
    EXPECT_FALSE(panelInteracting());
}

TEST(PanelInteracting, NotWhileATextFieldHasTheFocus) {
    HeadlessImGui imgui;
    Panel panel;
    imgui.frame(ImVec2(390, 290), false, [&] { panel.draw(); });
    // Clicked into, then typed into with the mouse away, for a while.
    imgui.frame(panel.textAt, false, [&] { panel.draw(); });
    imgui.frame(panel.textAt, true, [&] { panel.draw(); });
    imgui.frame(panel.textAt, false, [&] { panel.draw(); });
    for (int i = 0; i < 10; ++i) {
        if (i == 3) ImGui::GetIO().AddInputCharacter('5');
        imgui.frame(ImVec2(390, 290), false, [&] { panel.draw(); });
        ASSERT_TRUE(ImGui::IsAnyItemActive()) << "frame " << i << ": the text field lost the focus";
        EXPECT_FALSE(panelInteracting()) << "frame " << i;
    }
    EXPECT_STREQ(panel.text, "1605");
}

TEST(PanelInteracting, WhileASliderIsHeldOrDragged) {
    HeadlessImGui imgui;
    Panel panel;
    imgui.frame(ImVec2(390, 290), false, [&] { panel.draw(); });
    imgui.frame(panel.sliderAt, false, [&] { panel.draw(); });
    const ImVec2 at = panel.sliderAt;
    for (int i = 0; i < 6; ++i) {
        // Held still for three frames, then dragged right.
        imgui.frame(ImVec2(at.x + (i < 3 ? 0.0f : 10.0f * float(i)), at.y), true, [&] { panel.draw(); });
        EXPECT_TRUE(panelInteracting()) << "frame " << i;
    }
    EXPECT_GT(panel.value, 0.5f);
    imgui.frame(at, false, [&] { panel.draw(); });
    imgui.frame(at, false, [&] { panel.draw(); });
    EXPECT_FALSE(panelInteracting());
}

}  // namespace
}  // namespace woven
