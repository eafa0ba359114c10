#include "exposure_fold.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace woven {

namespace {

// How far the fold may move a channel of the light through the yarns (as the 5 % a fitted
// material must reproduce its photo within).
constexpr double kLightChangeLimit = 0.05;

std::string formatted(const char* format, double value) {
    char line[400];
    std::snprintf(line, sizeof line, format, value, value);
    return line;
}

// Each yarn channel's light through the yarns, t (1 - rs) (1 - R_d), weighted by how much of the
// channel a yarn passes ((R_d / max R_d)^2, which the fold leaves as it was); zero weight for a
// black yarn.
struct ChannelLight {
    double weight, before, after;  // after at t' = 1
};

std::vector<ChannelLight> channelLights(const WovenParams& p, const WovenParams& folded, double e) {
    std::vector<ChannelLight> lights;
    for (const auto& [before, after] : {std::pair{p.weft_color, folded.weft_color}, std::pair{p.warp_color, folded.warp_color}}) {
        const double peak = std::max({before.r, before.g, before.b});
        if (!(peak > 0.0)) continue;
        for (int c = 0; c < 3; ++c)
            lights.push_back({(before[c] / peak) * (before[c] / peak), e * p.transmission * (1.0 - p.rs) * (1.0 - before[c]),
                              (1.0 - folded.rs) * (1.0 - after[c])});
    }
    return lights;
}

// t' whose light through the yarns is E times the fitted one's, by weighted least squares.
double foldedTransmission(const std::vector<ChannelLight>& lights, double fallback) {
    double ab = 0.0, aa = 0.0;
    for (const ChannelLight& l : lights) {
        ab += l.weight * l.weight * l.after * l.before;
        aa += l.weight * l.weight * l.after * l.after;
    }
    return aa > 0.0 ? ab / aa : fallback;
}

// The largest relative change the fold makes to a channel's light through the yarns (where the
// channel passes a tenth of its yarn's strongest's at least).
double transmittedChange(const std::vector<ChannelLight>& lights, double t) {
    double worst = 0.0;
    for (const ChannelLight& l : lights)
        if (l.weight > 0.1 && l.before > 0.0) worst = std::max(worst, std::abs(t * l.after / l.before - 1.0));
    return worst;
}

bool withinOne(const glm::vec3& c) { return c.r <= 1.0f && c.g <= 1.0f && c.b <= 1.0f; }

}  // namespace

ExposureFold foldExposure(const WovenParams& fitted, double exposure) {
    ExposureFold out;
    out.params = fitted;
    out.factor = exposure;
    if (exposure == 1.0) return out;
    WovenParams p = fitted;
    p.rs = float(exposure * fitted.rs);
    const float diffuse = float(exposure * (1.0 - fitted.rs) / (1.0 - p.rs));
    p.weft_color = fitted.weft_color * diffuse;
    p.warp_color = fitted.warp_color * diffuse;
    for (glm::vec3& c : p.weft_colors) c *= diffuse;
    for (glm::vec3& c : p.warp_colors) c *= diffuse;
    double lightChange = 0.0;
    if (fitted.transmission > 0.0f) {
        const std::vector<ChannelLight> lights = channelLights(fitted, p, exposure);
        p.transmission = float(foldedTransmission(lights, fitted.transmission));
        lightChange = transmittedChange(lights, p.transmission);
    }
    const bool withinRange = p.rs < 1.0f && p.transmission <= 1.0f && withinOne(p.weft_color) && withinOne(p.warp_color) &&
                             std::all_of(p.weft_colors.begin(), p.weft_colors.end(), withinOne) &&
                             std::all_of(p.warp_colors.begin(), p.warp_colors.end(), withinOne);
    if (!withinRange) {
        out.note = formatted("the photos are brighter than any material with colours, rs and transmission up to 1 renders under the shots' "
                             "light: the light was about %.4g times brighter than the shots state, so the material is "
                             "kept as fitted, to be rendered with the lights %.4g times as bright",
                             exposure);
    } else if (lightChange > kLightChangeLimit) {
        char line[500];
        std::snprintf(line, sizeof line,
                      "the photos are %.4g times as bright as the shots' light gives; the backlit shot ties the colours "
                      "to that exposure (a yarn passes light as 1 - R_d), and folding it into the colours would change "
                      "the light through the yarns by up to %.0f %%, so the material is kept as fitted, to be rendered "
                      "with the lights %.4g times as bright",
                      exposure, 100.0 * lightChange, exposure);
        out.note = line;
    } else {
        out.params = p;
        out.folded = true;
        out.note = formatted("the fitted exposure %.4g is folded into the colours, rs and transmission (each "
                             "reflectance times %.4g): rendered under the shots' own light this material matches "
                             "the photos",
                             exposure);
    }
    return out;
}

ExposureFold foldFittedExposure(const std::vector<Shot>& shots, const FitResult& fit) {
    const bool allFree = std::all_of(shots.begin(), shots.end(), [](const Shot& s) { return !s.photo.exposure; });
    return foldExposure(fit.params, allFree ? fit.exposure : 1.0);
}

}  // namespace woven
