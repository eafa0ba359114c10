#pragma once
// A free exposure folded into the fitted material (docs/FIT.md, "Output"), so that the material
// rendered in the shots' own rig, at the light the shots state, matches the photos. A free
// exposure E scales every render; the material that renders E times as bright at the rig's
// near-normal flash has rs' = E rs and R_d' = E R_d (1 - rs) / (1 - rs') (MODEL.md section 4:
// the diffuse term carries 1 - rs), and the transmission t' whose light through the yarns,
// t' (1 - rs') (1 - R_d') per channel (docs/MODEL_TRANSMISSION.md), is E times the fitted one's
// in the least-squares sense over the channels that pass light. That is exact for reflection
// alone; where a backlit shot was fitted, its 1 - R_d tied the colours to the exposure (the
// fitted colours are the cloth's), and no t' passes E times the light in every channel unless E
// is near 1. So where the fold would move a channel of the light through the yarns by over 5 %,
// or a colour, rs or t would exceed 1 (the photos brighter than any material renders under the
// stated light), the material and the exposure are kept as fitted and the note says so. (Yarn
// types' own rs and transmission are not folded: the fit writes none.)
#include <string>
#include <vector>

#include "fabric_fit.h"
#include "shot.h"
#include "woven_params.h"

namespace woven {

struct ExposureFold {
    WovenParams params;  // folded where `folded`, else as fitted
    bool folded = false;
    double factor = 1.0;  // the exposure folded in, or kept
    std::string note;     // one sentence for stderr and the JSON's "comment"; empty at exposure 1
};

ExposureFold foldExposure(const WovenParams& fitted, double exposure);

// The fit's exposure folded into its material where every shot's exposure is free; where one is
// given, that shot's photo is to be rendered as fitted, and nothing is folded.
ExposureFold foldFittedExposure(const std::vector<Shot>& shots, const FitResult& fit);

}  // namespace woven
