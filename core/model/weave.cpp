#include "weave.h"

#include <algorithm>
#include <numeric>

namespace woven {

std::vector<Yarn> Weave::resolvedYarns(const WovenParams& p) {
    const Yarn warp = sideYarn(p, YarnSide::Warp), weft = sideYarn(p, YarnSide::Weft);
    std::vector<Yarn> yarns{warp, weft};
    for (const YarnSpec& type : p.yarns) yarns.push_back(resolve(type, warp));
    for (const YarnSpec& type : p.yarns) yarns.push_back(resolve(type, weft));
    return yarns;
}

ThreadLayout Weave::threads(const WovenParams& p, YarnSide side) {
    const int types = int(p.yarns.size());
    return side == YarnSide::Warp
               ? ThreadLayout(p.warp_colors, p.warp_yarns, p.warp_spacing, p.warp_color, 0, yarnOfType(0, side, types))
               : ThreadLayout(p.weft_colors, p.weft_yarns, p.weft_spacing, p.weft_color, 1, yarnOfType(0, side, types));
}

namespace {
// lcm(tile side, thread period) 2^k for the largest k that keeps it within 2^62: lcm <= 2^14 x
// 2^16 (woven_params.h), so k >= 32.
double wrapPeriod(int tileSide, int threadPeriod) {
    double period = std::ldexp(double(std::lcm(int64_t(tileSide), int64_t(threadPeriod))), 32);
    while (2.0 * period <= 0x1p62) period *= 2.0;
    return period;
}
}  // namespace

Weave::Weave(const WovenParams& p)
    : front_(WeavePattern::fromParams(p)),
      back_(front_.reversed()),
      floats_(p.crimp > 0.0f ? std::make_unique<const WeaveFloats>(front_) : nullptr),
      yarns_(resolvedYarns(p)),
      warp_(threads(p, YarnSide::Warp)),
      weft_(threads(p, YarnSide::Weft)),
      wrap_(wrapPeriod(front_.width(), warp_.period()), wrapPeriod(front_.height(), weft_.period())) {
    for (const Yarn& y : yarns_) shapes_.emplace_back(y.ex(), y.ey(), y.rs());
}

std::vector<Yarn> usedYarns(const WovenParams& p, YarnSide side) {
    const Yarn own = sideYarn(p, side);
    const std::vector<int>& types = side == YarnSide::Warp ? p.warp_yarns : p.weft_yarns;
    if (types.empty()) return {own};
    std::vector<bool> used(p.yarns.size(), false);
    for (int t : types) used[size_t(t)] = true;
    std::vector<Yarn> yarns;
    for (size_t t = 0; t < used.size(); ++t)
        if (used[t]) yarns.push_back(resolve(p.yarns[t], own));
    return yarns;
}

bool mayShowGaps(const WovenParams& p) {
    auto narrow = [&](YarnSide side) {
        for (const Yarn& yarn : usedYarns(p, side))
            if (yarn.width() < 1.0f) return true;
        return false;
    };
    return narrow(YarnSide::Warp) && narrow(YarnSide::Weft);
}

bool mayBeSeenThrough(const WovenParams& p) { return p.backing == 0 && mayShowGaps(p); }

bool hasNoise(const WovenParams& p) {
    for (YarnSide side : {YarnSide::Warp, YarnSide::Weft})
        for (const Yarn& yarn : usedYarns(p, side))
            if (yarn.noise() > 0.0f) return true;
    return false;
}

}  // namespace woven
