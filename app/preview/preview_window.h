#pragma once
// The interactive previewer: a GLFW window with an OpenGL core context, the scene drawn by
// PreviewRenderer, and a Dear ImGui panel to tune the woven material live (sliders generated
// from wovenParamTable()), pick weave presets, edit the material's draft (a .wif dropped on the
// window or opened from the panel: draft_view.h), save/load the material, and run the Render
// button's FinalRender with its progressive result shown in the window.
#include <string>

#include "frame_options.h"

namespace woven {

struct PreviewWindowOptions {
    std::string scene;           // empty: the procedural cloth
    // The --woven edits, the display transform and the Render button's settings, as `woven render`
    // takes them. width/height also size the window (default 1280x800); the Render button's size
    // is the scene's, else the window's.
    FrameOptions frame;
    int frames = 0;              // quit after this many frames; 0 = until the window is closed
    std::string screenshot;      // PNG of the last frame (panel included), written before quitting (not
                                 // when the window is closed by its close button)
    std::string draft;           // a WIF file to open on the first woven material at start
    // Each frame, the panel's widgets (label, ImGui ID, rectangle) and the window's state as JSON
    // (widget_map.h), written whole: for tests that click through the window.
    std::string widgetMap;
    bool rendered = false;       // the view starts in Rendered mode (rendered_viewport.h)
};

// Runs until the window closes (or `frames` frames, or SIGINT or SIGTERM). Throws GlError when no window or context
// can be had, std::runtime_error when the initial scene cannot be loaded.
void runPreviewWindow(const PreviewWindowOptions& options);

}  // namespace woven
