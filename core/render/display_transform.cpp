#include "display_transform.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "atomic_file.h"
#include "image_io.h"
#include "srgb.h"

namespace woven {

namespace {

float toneMap(float c, ToneMap curve) {
    switch (curve) {
        case ToneMap::Clamp: return c;
        case ToneMap::Reinhard: return c / (1.0f + c);
        case ToneMap::Aces:
            return (c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f);
    }
    return c;
}

}  // namespace

glm::u8vec3 displayColor(const glm::vec3& linear, const DisplayTransform& transform) {
    const float scale = std::exp2(transform.exposure);
    glm::u8vec3 out;
    for (int c = 0; c < 3; ++c) {
        // Negative values are black before the curve: ACES's rational fit turns large negative
        // values positive. NaN (a bug upstream) shows as black rather than undefined behaviour.
        float v = toneMap(std::max(linear[c] * scale, 0.0f), transform.toneMap);
        v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
        out[c] = static_cast<unsigned char>(std::lround(linearToSrgb(v) * 255.0f));
    }
    return out;
}

void writePng(const std::string& path, const Image& image, const DisplayTransform& transform) {
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * image.height)
        throw ImageError(path + ": cannot write an empty or inconsistent image");
    std::vector<glm::u8vec3> bytes(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) bytes[i] = displayColor(image.pixels[i], transform);
    writeFileAtomically(path, [&](const std::string& tmp) {
        if (!stbi_write_png(tmp.c_str(), image.width, image.height, 3, &bytes[0].x, image.width * 3))
            throw ImageError("cannot write the PNG data");
    });
}

}  // namespace woven
