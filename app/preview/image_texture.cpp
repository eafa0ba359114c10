#include "image_texture.h"

#include <cstdint>
#include <vector>

namespace woven {

void uploadImageTexture(GLuint texture, const Image& image, const DisplayTransform& transform) {
    std::vector<uint8_t> bytes(image.pixels.size() * 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::u8vec3 c = displayColor(image.pixels[i], transform);
        bytes[4 * i] = c.r;
        bytes[4 * i + 1] = c.g;
        bytes[4 * i + 2] = c.b;
        bytes[4 * i + 3] = 255;
    }
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

}  // namespace woven
