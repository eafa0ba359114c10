#pragma once
// woven fit's optimiser (docs/FIT.md): the woven material whose renders of the shots have the
// photos' statistics. In stages, each starting from the last one's best:
//   1. thread counts from the photo's spectrum (power_spectrum.h): the peak of each thread
//      direction, which the shot's camera turns into threads per UV unit (Shot::uvPerPixel);
//   2. the weave: each of weaveCandidates() with its yarn colours fitted (by NLopt, on mixtures
//      of renders whose mixtures are exact for any colours under direct light from point lights:
//      one render with the weft red and the warp green under white light, else three), the best
//      kept; where backlit shots join reflected ones, on the reflected shots alone (fabric_fit.cpp
//      says why);
//   3. the thread counts once more, the chosen weave's render's peaks against the photo's;
//   4. gloss (ex, ey, and rs where no exposure is free), yarn widths and bump (cy) by NLopt's
//      BOBYQA, the colours and a free exposure solved in closed form at each point from the same
//      mixtures (linear_colours.h), until the time budget is spent (less what stage 5 costs);
//   5. the colours solved once more at the best shape from renders at 4 times the samples.
// Where some shots are lit from behind (Shot::backlit) and others not, each point of stage 4
// also renders the backlit shots' six parts (transmitted_colours.h: the weft alone, the warp
// alone and their crossings, each with the transmission's diffuse and glossy part, in two
// renders under white light), and the colours, the exposure and the transmission
// (transmission, transmission_gloss) are solved against every shot together, with rs where the
// exposure is free.
// The best parameters met are kept throughout: a cancelled or timed-out fit returns them.
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "fit_loss.h"
#include "shot.h"
#include "shot_render.h"

namespace woven {

struct FitOptions {
    double seconds = 180.0;  // the time budget
    int renders = 0;         // a budget of renders besides (0: none), which makes a fit repeatable;
                             // stage 5's few renders come after it
    FitRenderSettings render;
};

struct FitProgress {
    std::string stage;
    int evaluations = 0;  // renders so far
    double elapsed = 0.0, budget = 0.0;
    double bestLoss = 0.0;
};

struct ShotFit {
    LossTerms terms;  // of the best parameters
    Image render;     // the best parameters' render, vignette and exposure applied
    // The photo's and the render's thread frequencies, cycles per pixel (0: no peak found), and the
    // angle between the photo's thread directions and the render's, degrees.
    glm::dvec2 photoFrequency{0.0}, renderFrequency{0.0};
    glm::dvec2 directionError{0.0};
    // The block means' error (LossTerms) of the best Lambertian plane under the shot's light: a
    // white one rendered, each channel scaled to the photo by least squares. What the fit's own
    // block means' error should beat: the light's fall-off and the highlight. Negative where the
    // shot is backlit (a Lambertian plane passes no light).
    double lambertianBlockMeansError = -1.0;
};

struct FitResult {
    WovenParams params;
    double exposure = 1.0;  // the free shots' exposure (1 when none is free)
    double loss = 0.0;  // at stage 5's samples where it ran (a render's noise counts in the spectrum)
    std::vector<ShotFit> shots;
    // (seconds, best loss) after each evaluation; stage 5's at its own samples, so the last may jump
    std::vector<std::pair<double, double>> history;
    int evaluations = 0;
    bool complete = false;  // every stage ran (not cancelled, the budget was enough)
    std::vector<std::string> warnings;
};

FitResult fitFabric(const std::vector<Shot>& shots, const FitOptions& options, const std::atomic<bool>& cancel,
                    const std::function<void(const FitProgress&)>& onProgress = {});

// What fitFabric() makes of one material: its loss, terms and render (one render of each shot),
// for a known material's loss beside a fit's.
FitResult fitLoss(const std::vector<Shot>& shots, const WovenParams& params, const FitOptions& options);

}  // namespace woven
