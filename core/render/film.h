#pragma once
// The film of a final frame: per pixel the sum of its camera samples and of the splats that
// BDPT's light paths seen by the camera (t = 1) land in, the count of passes that sampled it
// (one sample per pixel each; every pass unless sampling is adaptive), and the sums its render
// passes are means of (render_passes.h: first hits, squares for the variance). The sums are exact
// (ExactSum), so the image is a pure function of the samples it holds: whatever threads rendered
// them, in whatever order, and the merge of renders of disjoint sample ranges gives the same
// image bit for bit.
#include <cstdint>
#include <vector>

#include "frame_io.h"
#include "render_passes.h"
#include "sample_contributions.h"

namespace woven {

// Mean radiance and sample count per pixel, and what an EXR keeps so that renders of disjoint
// sample ranges merge exactly (frame_io.h): the exact sums, the sample range and the frame.
struct FilmImage {
    Image radiance;          // linear RGB mean: the noisy beauty
    std::vector<float> sampleCount;  // per pixel
    std::vector<ExactSum> sampleSums{};  // R, G, B per pixel
    SampleRange samples{};
    FrameIdentity frame{};
    std::vector<PassSums> passSums{};  // per pixel
    // The denoised beauty, once a denoiser has made it from radiance and passes(); a frame file
    // then shows it as its beauty and keeps radiance beside it (ExrImage::noisy).
    std::optional<Image> denoised{};

    RenderPasses passes() const {
        return meanPasses(radiance.width, radiance.height, sampleCount, sampleSums, passSums);
    }
    // As a frame file keeps it (writeFrame): everything `woven merge` needs.
    ExrImage exr() const {
        if (!denoised) return {radiance, sampleCount, sampleSums, samples, frame, passSums};
        return {*denoised, sampleCount, sampleSums, samples, frame, passSums, radiance};
    }
};

// One pass before it is added: each pixel's estimate, and the splats of each tile in tile order.
struct PassImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> radiance;           // row-major, one per pixel
    std::vector<FirstHit> firstHits;           // row-major, one per pixel
    std::vector<std::vector<Splat>> tileSplats;
    // An adaptive pass (adaptive_sampling.h) samples only some pixels: 1 for those (empty: all).
    // BDPT then traces one light subpath per sampled pixel, not per pixel, so each splat is
    // scaled by pixels / sampled pixels to keep the pass an unbiased estimate of every pixel it
    // sampled; splats on the others are dropped, as those pixels take no more samples.
    std::vector<uint8_t> sampled;
    float splatScale = 1.0f;

    bool samples(size_t pixel) const { return sampled.empty() || sampled[pixel] != 0; }
    // The pass as an image of its own, splats added: one independent estimate of each pixel it
    // sampled (0 elsewhere).
    std::vector<glm::vec3> combined() const;
    // Calls f(pixel, L) for each splat that lands on a sampled pixel, scaled, in tile order.
    template <typename F>
    void forEachSplat(F&& f) const;
};

// The pixel a raster position falls in (box filter of one pixel); -1 outside the image.
int pixelIndex(const glm::vec2& pRaster, int width, int height);

class Film {
public:
    // `passes` false: the render passes' sums are not kept (FilmImage::passSums empty).
    Film(int width, int height, bool passes = true);

    void addPass(const PassImage& pass);
    // Mean radiance: (samples + splats) / count. pbrt-v3 scales its splat buffer by 1 / spp, which
    // is the same when every pixel's count is the number of passes (PassImage::splatScale tells
    // why it stays right when it is not). `samples` is left empty: the film
    // does not know which sample indices its passes were.
    FilmImage image() const;
    // Its radiance alone (image().radiance): what a progressive view shows after each pass,
    // without copying the sums and passes that a frame file and the denoiser need.
    Image meanRadiance() const;
    int passes() const { return passes_; }

private:
    int width_, height_, passes_ = 0;
    std::vector<ExactSum> sum_;  // R, G, B per pixel
    std::vector<float> count_;
    std::vector<PassSums> passSums_;  // empty where the film keeps no passes
};

template <typename F>
void PassImage::forEachSplat(F&& f) const {
    for (const auto& splats : tileSplats)
        for (const Splat& s : splats) {
            const int i = pixelIndex(s.pRaster, width, height);
            if (i >= 0 && samples(size_t(i))) f(size_t(i), splatScale == 1.0f ? s.L : s.L * splatScale);
        }
}

}  // namespace woven
