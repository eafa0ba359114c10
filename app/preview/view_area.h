#pragma once
// Where the window shows an image in place of the preview (the Render button's frame, the
// Rendered view's): the part of the window the panel leaves free. Within an ImGui frame.
#include <epoxy/gl.h>
#include <imgui.h>

namespace woven {

// The part of the window the panel leaves free on its right (the whole window when the panel is
// collapsed or elsewhere): x0, y0, x1, y1.
ImVec4 viewArea();
// `texture` letterboxed in viewArea() (row 0 of the image at its top), over a black window.
void drawInView(GLuint texture, float imageAspect);

}  // namespace woven
