#pragma once
// The one exception type of the previewer's OpenGL layer: no context could be made, a shader
// did not compile, a framebuffer is incomplete. The message says what failed and why.
#include <stdexcept>

namespace woven {

struct GlError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace woven
