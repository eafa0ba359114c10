#include "film.h"

#include <cmath>

namespace woven {

int pixelIndex(const glm::vec2& pRaster, int width, int height) {
    const float fx = std::floor(pRaster.x), fy = std::floor(pRaster.y);
    if (!(fx >= 0.0f && fy >= 0.0f && fx < float(width) && fy < float(height))) return -1;
    return int(fy) * width + int(fx);
}

std::vector<glm::vec3> PassImage::combined() const {
    std::vector<glm::vec3> image = radiance;
    for (const auto& splats : tileSplats)
        for (const Splat& s : splats) {
            const int i = pixelIndex(s.pRaster, width, height);
            if (i >= 0) image[size_t(i)] += s.L;
        }
    return image;
}

Film::Film(int width, int height)
    : width_(width), height_(height), sum_(size_t(width) * height, glm::dvec3(0.0)),
      splat_(size_t(width) * height, glm::dvec3(0.0)), count_(size_t(width) * height, 0.0f) {}

void Film::addPass(const PassImage& pass) {
    for (size_t i = 0; i < sum_.size(); ++i) {
        sum_[i] += glm::dvec3(pass.radiance[i]);
        count_[i] += 1.0f;
    }
    for (const auto& splats : pass.tileSplats)
        for (const Splat& s : splats) {
            const int i = pixelIndex(s.pRaster, width_, height_);
            if (i >= 0) splat_[size_t(i)] += glm::dvec3(s.L);
        }
    ++passes_;
}

FilmImage Film::image() const {
    FilmImage out;
    out.radiance.width = width_;
    out.radiance.height = height_;
    out.radiance.pixels.assign(sum_.size(), glm::vec3(0.0f));
    out.sampleCount = count_;
    for (size_t i = 0; i < sum_.size(); ++i)
        if (count_[i] > 0.0f) out.radiance.pixels[i] = glm::vec3((sum_[i] + splat_[i]) / double(count_[i]));
    return out;
}

}  // namespace woven
