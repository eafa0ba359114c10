#pragma once
// The weave's repeat folded (docs/FIT.md, "How it compares"): the mean colour of an image at each
// place of one repeat of its weave, every repeat the image shows laid on top of the others, as
// astronomers fold a periodic signal on its period. It sees each yarn's colour where it floats,
// the gaps and the gloss across a thread, which the whole image's statistics mix. It needs the
// threads' frequencies but no alignment: the fold starts where the threads' fundamentals peak,
// and two folds are compared at the circular shift that matches them best, so that a photo and a
// render whose threads lie elsewhere still compare.
#include <vector>

#include <glm/glm.hpp>

#include "image.h"

namespace woven {

// Where an image's threads are: cycles per pixel of the warp ends (the weave's U grows along
// `ends`) and of the weft picks (V along `picks`), and the weave's repeat in threads either way.
struct ThreadGrid {
    glm::dvec2 ends{0.0}, picks{0.0};
    int period = 1;
};

struct TileFold {
    int side = 0;                  // bins a side: kFoldBinsPerThread x the grid's period
    std::vector<glm::vec3> mean;   // side x side, row V first
    std::vector<float> weight;     // the pixels' share in each bin (0: none fell there)
};

TileFold foldTile(const Image& image, const ThreadGrid& grid);

// The folds of `images` at the phase of `reference`'s fold, each bin moved by the shift that
// foldError() lays `reference`'s fold on `photo`'s with, so that bin b of each pairs with the
// photo's bin b. At one phase and shift a fold is linear in the image: for renders that sum to
// `reference` (a render's parts linear in the yarn colours) the folds sum to its fold.
std::vector<TileFold> foldsLaidOn(const TileFold& photo, const Image& reference, const std::vector<const Image*>& images,
                                  const ThreadGrid& grid);

// The bins that both folds fill, laid bin by bin (foldsLaidOn()): those a linear solve compares.
std::vector<size_t> sharedBins(const TileFold& photo, const TileFold& laid);

// The mean of each channel over the bins a fold fills: the scale of foldError()'s differences.
glm::dvec3 foldChannelMeans(const TileFold& photo);

// The frequency near `f` (cycles per pixel, x and y) at which the luminance `values` (width x
// height) folded on one thread is sharpest: the largest variance of its mean profile across the
// thread, searched over the frequency's length within a bin of the image's spectrum (at most 3 %)
// and its direction within 1.5 degrees.
// Phase dispersion minimisation (Stellingwerf 1978): a spectrum's peak is only as sharp as the
// image is wide, and the weave's own peaks beside it pull it, while a fold drifts off the threads
// by the frequency's error times the threads the image shows, so the fold is the finer measure.
glm::dvec2 refineThreadFrequency(const std::vector<float>& values, int width, int height, const glm::dvec2& f);

// Mean of ((render - photo) / the photo's channel mean)^2 over the bins both folds fill, at
// the circular shift of the render's fold whose luminance matches the photo's best. 0 when the
// folds differ in size or either is empty.
double foldError(const TileFold& photo, const TileFold& render);

}  // namespace woven
