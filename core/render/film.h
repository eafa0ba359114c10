#pragma once
// The film of a final frame: per pixel the sum of its camera samples and of the splats that
// BDPT's light paths seen by the camera (t = 1) land in, and the count of passes (one sample per
// pixel each). The sums are exact (ExactSum), so the image is a pure function of the samples it
// holds: whatever threads rendered them, in whatever order, and the merge of renders of disjoint
// sample ranges gives the same image bit for bit.
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
    // Mean radiance: (samples + splats) / count. pbrt-v3 scales its splat buffer by 1 / spp, which
    // is the same: every pixel's count is the number of passes. `samples` is left empty: the film
    // does not know which sample indices its passes were.
    FilmImage image() const;
    int passes() const { return passes_; }

private:
    int width_, height_, passes_ = 0;
    std::vector<ExactSum> sum_;  // R, G, B per pixel
    std::vector<float> count_;
};

}  // namespace woven
