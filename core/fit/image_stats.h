#pragma once
// Statistics of an image that need no alignment (docs/FIT.md, "How it compares"): the threads of
// a photo and of a render never line up, so the fit compares what stays when they are shifted.
//   block means    the mean colour over an 8 x 8 grid: the light's fall-off and the highlight
//   quantiles      each channel's 10 ... 90 % quantiles over a 4 x 4 grid: how the yarns' colours
//                  and the highlight spread within a region, whatever the threads' phase
//   spectrum       each channel's power spectrum (power_spectrum.h), summed over bins of 1/32
//                  cycle per pixel, in log10: the weave's class, direction and thread counts
//   thread peaks   each channel's amplitude (the root of the power) at the photo's thread
//                  frequencies, ends and picks: which yarn has which colour, as the ends' peak
//                  is the warp's cross-section and the picks' the weft's
//   gram           the second moments of the features (R, G, B, |d/dx|, |d/dy|) over the image,
//                  as a Gram matrix of image features does for texture: which colour the edges
//                  across each direction have
//   tile fold      the mean colour at each place of one repeat of the weave (tile_fold.h): each
//                  yarn's colour where it floats, where a thread grid is given
#include <array>
#include <vector>

#include "image.h"
#include "tile_fold.h"

namespace woven {

enum StatGroup { kStatBlockMeans, kStatQuantiles, kStatSpectrum, kStatThreadPeaks, kStatGram, kStatTileFold, kStatGroupCount };
const std::array<const char*, kStatGroupCount>& statGroupNames();  // "block means", ...

struct ImageStats {
    std::array<std::vector<float>, kStatGroupCount> values;  // all but the tile fold's
    TileFold fold;
};

// `threads`: the frequencies (cycles per pixel, x and y) the thread peaks are read at; none, no
// thread peaks. `grid`: where the image's threads are; none, no tile fold.
ImageStats imageStats(const Image& image, const std::vector<glm::dvec2>& threads, const ThreadGrid* grid = nullptr);
std::vector<float> blockMeans(const Image& image);  // imageStats()'s first group alone

}  // namespace woven
