#pragma once
// A linear RGB float image, the frames, environment maps and photographs every layer passes
// around: in a header of its own so that drafts, the denoiser and the fit need not include the
// scene description for it.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace woven {

// Row 0 at the top.
struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * width + x]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

}  // namespace woven
