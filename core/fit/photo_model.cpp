#include "photo_model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "image_io.h"
#include "short_number.h"

namespace woven {

namespace {

bool holdsFloats(const std::string& path) {
    const std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    return ext == ".exr" || ext == ".hdr" || ext == ".EXR" || ext == ".HDR";
}

// Throws ImageError when `image` holds nothing to fit (readPhoto()).
void checkSignal(const Image& image, const std::string& path) {
    double lowest = INFINITY, highest = -INFINITY, sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3& p = image.pixels[i];
        if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
            throw ImageError(path + ": pixel (" + std::to_string(i % size_t(image.width)) + ", " +
                             std::to_string(i / size_t(image.width)) + ") is not a finite number: a photo to fit holds none");
        const double l = luminance(p);
        lowest = std::min(lowest, l);
        highest = std::max(highest, l);
        sum += l;
    }
    const double mean = image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
    // All black is data (an opaque cloth lit from behind passes nothing); any other uniform image
    // holds no weave.
    if (highest > 0.0 && !(highest - lowest > 0.01 * mean))
        throw ImageError(path + ": every pixel is within 1% of the mean (" + shortNumber(mean) +
                         "): the photo shows no weave to fit (a uniform or all-clipped image)");
}

}  // namespace

Image readPhoto(const ShotPhoto& photo) {
    Image image = readImage(photo.image, photo.encoding == ShotPhoto::Encoding::Srgb ? ChannelEncoding::Srgb : ChannelEncoding::Linear);
    // A float file holds linear values whatever the key says; only 8- and 16-bit ones are encoded.
    if (photo.encoding == ShotPhoto::Encoding::Gamma22 && !holdsFloats(photo.image))
        for (glm::vec3& p : image.pixels) p = glm::pow(glm::max(p, glm::vec3(0.0f)), glm::vec3(2.2f));
    checkSignal(image, photo.image);
    return image;
}

float photoSaturation(const ShotPhoto& photo) { return holdsFloats(photo.image) ? INFINITY : 1.0f; }

void applyVignette(Image& image, float sigmaPx) {
    if (!(sigmaPx > 0.0f)) return;
    const float cx = 0.5f * float(image.width), cy = 0.5f * float(image.height);
    const float k = -0.5f / (sigmaPx * sigmaPx);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
            image.at(x, y) *= std::exp(k * (dx * dx + dy * dy));
        }
}

double bestExposure(const std::vector<float>& photo, const std::vector<float>& render) {
    double pr = 0.0, rr = 0.0;
    for (size_t i = 0; i < photo.size() && i < render.size(); ++i) {
        pr += double(photo[i]) * render[i];
        rr += double(render[i]) * render[i];
    }
    return rr > 0.0 ? pr / rr : 1.0;
}

void expose(Image& image, float exposure, float saturation) {
    for (glm::vec3& v : image.pixels) v = glm::min(v * exposure, glm::vec3(saturation));
}

}  // namespace woven
