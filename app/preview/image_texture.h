#pragma once
// An image shown in the window through ImGui: the rendered frame over the preview, the Fabrics
// menu's thumbnails. Its pixels (linear RGB) go through the display transform of PNG output.
#include <epoxy/gl.h>

#include "display_transform.h"
#include "image_io.h"

namespace woven {

// Loads `image` into the 2D texture `texture` (made with glGenTextures), linearly filtered.
void uploadImageTexture(GLuint texture, const Image& image, const DisplayTransform& transform);

}  // namespace woven
