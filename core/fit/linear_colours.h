#pragma once
// The yarn colours in closed form (docs/FIT.md, stage 4). Under direct light from point lights a
// render is linear in the two yarns' colours, channel by channel:
//     render = weft x K_weft + warp x K_warp + R,
// K_weft, K_warp and R (the gloss and whatever is not a yarn) being renders of the same shape. So
// are the block means, and the tile fold at a fixed phase and shift (those of the mixture at the
// colours so far), and the colours that best match them solve a linear least-squares problem.
// With a free exposure e the photo is e x render, linear in e x weft, e x warp and e together:
// only those products are seen, and they are solved for jointly (holding e while the colours are
// solved let it drift, the synthetic plain weave's to 0.92 for 0.5).
#include <array>
#include <optional>
#include <vector>

#include "image_stats.h"

namespace woven {

// One shot's statistics of K_weft, K_warp and R (in that order), vignetted as the renders are.
struct LinearStats {
    std::array<std::vector<float>, 3> blockMeans;
    std::array<TileFold, 3> folds;  // laid on the photo's fold bin by bin (foldsLaidOn); side 0: none
};

struct LinearColours {
    glm::dvec3 weft{0.0}, warp{0.0};
    double exposure = 1.0;  // the free exposure, or 1 where every shot's is given
    bool valid = false;     // false: the problem was singular or the exposure came out <= 0
};

// The colours (and a free exposure shared by all shots) minimising the loss's block means' and
// tile fold's terms, weighted as lossWeights() weighs them, of each photo against exposure x
// (weft K_weft + warp K_warp + R). `exposures`: each shot's given exposure, or none where it is
// free; either all are free or none is.
LinearColours solveColours(const std::vector<const ImageStats*>& photos, const std::vector<LinearStats>& renders,
                           const std::vector<std::optional<double>>& exposures);

// The weighted sum of squares solveColours() minimises, at the given colours and free exposure
// (ignored where every exposure is given), R scaled by `gloss` where the exposure is free.
double colourResidual(const std::vector<const ImageStats*>& photos, const std::vector<LinearStats>& renders,
                      const std::vector<std::optional<double>>& exposures, const glm::dvec3& weft, const glm::dvec3& warp,
                      double exposure, double gloss = 1.0);

}  // namespace woven
