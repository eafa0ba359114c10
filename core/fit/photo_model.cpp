#include "photo_model.h"

#include <cmath>

#include "image_io.h"

namespace woven {

namespace {

bool holdsFloats(const std::string& path) {
    const std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    return ext == ".exr" || ext == ".hdr" || ext == ".EXR" || ext == ".HDR";
}

}  // namespace

Image readPhoto(const ShotPhoto& photo) {
    if (photo.encoding == ShotPhoto::Encoding::Srgb) return readImage(photo.image, ChannelEncoding::Srgb);
    Image image = readImage(photo.image, ChannelEncoding::Linear);
    // A float file holds linear values whatever the key says; only 8- and 16-bit ones are encoded.
    if (photo.encoding == ShotPhoto::Encoding::Gamma22 && !holdsFloats(photo.image))
        for (glm::vec3& p : image.pixels) p = glm::pow(glm::max(p, glm::vec3(0.0f)), glm::vec3(2.2f));
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
