#include "film.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "luminance.h"

namespace woven {

int pixelIndex(const glm::vec2& pRaster, int width, int height) {
    const float fx = std::floor(pRaster.x), fy = std::floor(pRaster.y);
    if (!(fx >= 0.0f && fy >= 0.0f && fx < float(width) && fy < float(height))) return -1;
    return int(fy) * width + int(fx);
}

std::vector<glm::vec3> PassImage::combined() const {
    std::vector<glm::vec3> image = radiance;
    forEachSplat([&](size_t i, const glm::vec3& L) { image[i] += L; });
    return image;
}

Film::Film(int width, int height, bool passes)
    : width_(width), height_(height), sum_(3 * size_t(width) * height), count_(size_t(width) * height, 0.0f),
      passSums_(passes ? size_t(width) * height : 0) {}

void Film::addPass(const PassImage& pass) {
    const std::vector<glm::vec3> estimate = passSums_.empty() ? std::vector<glm::vec3>{} : pass.combined();
    // Each pixel's sums are its own: any order, any thread (the calling arena's), the same sums.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count_.size(), 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (!pass.samples(i)) continue;
            count_[i] += 1.0f;
            for (int c = 0; c < 3; ++c) sum_[3 * i + size_t(c)].add(pass.radiance[i][c]);
            if (passSums_.empty()) continue;
            PassSums& p = passSums_[i];
            const FirstHit& hit = pass.firstHits[i];
            for (int c = 0; c < 3; ++c) {
                p.albedo[c].add(hit.albedo[c]);
                p.normal[c].add(hit.normal[c]);
                p.direct[c].add(hit.direct[c]);
                p.square[c].add(estimate[i][c] * estimate[i][c]);
            }
            p.depth.add(hit.depth);
            const float directLuminance = luminance(hit.direct);
            p.directSquare.add(directLuminance * directLuminance);
        }
    });
    pass.forEachSplat([&](size_t i, const glm::vec3& L) {
        for (int c = 0; c < 3; ++c) sum_[3 * i + size_t(c)].add(L[c]);
    });
    ++passes_;
}

FilmImage Film::image() const {
    FilmImage out;
    out.radiance = meanRadiance();
    out.sampleCount = count_;
    out.sampleSums = sum_;
    out.passSums = passSums_;
    return out;
}

Image Film::meanRadiance() const {
    Image radiance;
    radiance.width = width_;
    radiance.height = height_;
    radiance.pixels.resize(count_.size());
    for (size_t i = 0; i < count_.size(); ++i)
        for (int c = 0; c < 3; ++c) radiance.pixels[i][c] = sum_[3 * i + size_t(c)].mean(count_[i]);
    return radiance;
}

}  // namespace woven
