#pragma once
// A yarn as shading uses it: every yarn field of MODEL.md section 6 with its value, for one side
// of the cloth. The material's warp and weft parameters are the two default yarns; a yarn type
// (WovenParams::yarns, a YarnSpec) becomes one yarn per side, its unset fields taken from that side.
#include <array>

#include "woven_params.h"

namespace woven {

struct Yarn {
    std::array<float, kYarnFieldCount> value{};

    float ex() const { return value[kYarnEx]; }
    float ey() const { return value[kYarnEy]; }
    float rs() const { return value[kYarnRs]; }
    float width() const { return value[kYarnWidth]; }
    float cy() const { return value[kYarnCy]; }
    float noise() const { return value[kYarnNoise]; }
    float transmission() const { return value[kYarnTransmission]; }
    float transmissionGloss() const { return value[kYarnTransmissionGloss]; }
};

// The material's own yarn for the threads of `side` (Warp or Weft): warp_ex, warp_ey, rs,
// warp_width, cy, noise, transmission, transmission_gloss for the warp; ex, ey, rs, yarn_width, ... for the weft.
Yarn sideYarn(const WovenParams& p, YarnSide side);

// `type` on the threads of a side whose own yarn is `sideDefault`.
Yarn resolve(const YarnSpec& type, const Yarn& sideDefault);

}  // namespace woven
