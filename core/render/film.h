#pragma once
// The film of a final frame: per pixel the sum of its camera samples and their count, plus the
// splat buffer that BDPT's light paths seen by the camera (t = 1) land in. Filled one pass (one
// sample per pixel) at a time, always in the same order, so the image is a pure function of the
// passes it holds, whatever threads rendered them.
#include <vector>

#include "integrator.h"
#include "render_job.h"

namespace woven {

// One pass before it is added: each pixel's estimate, and the splats of each tile in tile order.
struct PassImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> radiance;           // row-major, one per pixel
    std::vector<std::vector<Splat>> tileSplats;

    // The pass as an image of its own, splats added: one independent estimate of the frame.
    std::vector<glm::vec3> combined() const;
};

// The pixel a raster position falls in (box filter of one pixel); -1 outside the image.
int pixelIndex(const glm::vec2& pRaster, int width, int height);

class Film {
public:
    Film(int width, int height);

    void addPass(const PassImage& pass);
    // Mean radiance: sum / count plus the splats divided by the number of passes (pbrt-v3 scales
    // its splat buffer by 1 / spp), which equals every pixel's count.
    FilmImage image() const;
    int passes() const { return passes_; }

private:
    int width_, height_, passes_ = 0;
    // Double sums: thousands of passes and merges of sample ranges stay exact to float precision.
    std::vector<glm::dvec3> sum_, splat_;
    std::vector<float> count_;
};

}  // namespace woven
