#pragma once
// The yarn colours solved against the reflected and the backlit shots together (docs/FIT.md,
// "The backlit shot"). A backlit photo shows each yarn's body transmittance
// T = t (1 - R_d) (R_d / max R_d)^2 (MODEL_TRANSMISSION.md 1), the smaller of the two yarns' where
// the light crosses both: not linear in the colours R_d, but linear, channel by channel, in the
// transmittance of three regions (the weft alone, the warp alone, both crossing) times the
// transmission's diffuse part T_d = t (1 - g) and glossy part T_g = t g. Renders of those six
// parts at t = 1 make a backlit render for any colours, t and g without rendering again.
//
// Why solve them together: a flash beside the lens lights the white gloss and the yarns'
// diffuse colour from the same direction, so a reflected photo alone confuses a grey share of a
// yarn's colour with the gloss (the round trips' colours came out a grey offset off, docs/FIT.md).
// The light through a yarn has no white gloss, and its hue, deepened by (R_d / max R_d)^2, moves
// with that grey share.
#include <array>
#include <optional>
#include <vector>

#include "image_stats.h"
#include "linear_colours.h"

namespace woven {

enum TransmittedRegion { kWeftAlone, kWarpAlone, kCrossing, kTransmittedRegionCount };

// One backlit shot's statistics of its six parts at t = 1: [region] for the diffuse part (g = 0)
// and [3 + region] for the glossy part (g = 1), vignetted as the renders are, each region's at a
// transmittance of 1 in every channel.
struct TransmissionStats {
    std::array<std::vector<float>, 2 * kTransmittedRegionCount> blockMeans;
    std::array<TileFold, 2 * kTransmittedRegionCount> folds;  // laid on the photo's fold (foldsLaidOn); side 0: none
};

// Each region's transmittance per unit t: the weft's, the warp's and their smaller per channel.
std::array<glm::dvec3, kTransmittedRegionCount> regionTransmittances(const glm::dvec3& weft, const glm::dvec3& warp);

struct TransmissionSplit {
    double diffuse = 0.0, glossy = 0.0;  // T_d = t (1 - g) and T_g = t g
    double transmission() const { return diffuse + glossy; }
    double gloss() const { return transmission() > 0.0 ? glossy / transmission() : 0.0; }
};

// The backlit shots' T_d and T_g (neither below 0) that best match their photos' block means,
// relative to each channel's mean as the loss weighs them, at the given colours; `exposures`
// each backlit shot's.
TransmissionSplit solveTransmission(const std::vector<const ImageStats*>& photos,
                                    const std::vector<TransmissionStats>& parts, const std::vector<double>& exposures,
                                    const glm::dvec3& weft, const glm::dvec3& warp);

struct TransmittedColours {
    LinearColours colours;
    TransmissionSplit split;
    double rsScale = 1.0;  // the factor on the reflected shots' R (their renders' rs); 1 where not solved
};

// The colours, a free exposure and the transmission minimising the block means' and tile fold's
// terms of the reflected shots (as solveColours() weighs them) and of the backlit shots together,
// by NLopt's BOBYQA from each of `starts`, the best kept. With a free exposure and `solveRs`, a
// factor on the reflected shots' R too (R the gloss alone, which rs scales): a reflected photo
// shows only exposure x rs, as it shows exposure x colour, and held at the renders' rs where the
// truth's differs it biased the colours (the backlit shot ties the exposure to the colours
// through T's factor 1 - R_d: docs/FIT.md). `reflectedExposures` as for
// solveColours(); `backlitExposures` each backlit shot's, none where it shares the free one.
TransmittedColours solveColoursWithTransmission(const std::vector<const ImageStats*>& reflectedPhotos,
                                                const std::vector<LinearStats>& reflected,
                                                const std::vector<std::optional<double>>& reflectedExposures,
                                                const std::vector<const ImageStats*>& backlitPhotos,
                                                const std::vector<TransmissionStats>& backlit,
                                                const std::vector<std::optional<double>>& backlitExposures,
                                                const std::vector<LinearColours>& starts, bool solveRs);

}  // namespace woven
