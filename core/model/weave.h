#pragma once
// Everything about a material's weave that a shading point looks up, built once per material:
// the tile of each face, the floats (only when the crimp needs them), the threads of each side
// (ThreadLayout) and the yarns they name. A material with no per-thread lists has one thread a
// side, carrying the material's colours and its two default yarns.
#include <cmath>
#include <memory>
#include <vector>

#include "ashikhmin_shirley.h"
#include "thread_layout.h"
#include "weave_pattern.h"
#include "yarn.h"

namespace woven {

class Weave {
public:
    explicit Weave(const WovenParams& p);  // `p` must be valid (validate())

    const WeavePattern& pattern(bool backSide) const { return backSide ? back_ : front_; }
    const WeaveFloats* floats() const { return floats_.get(); }  // null for a material without crimp
    const ThreadLayout& warp() const { return warp_; }
    const ThreadLayout& weft() const { return weft_; }

    // The resolved yarns: 0 the warp's own, 1 the weft's own, then each yarn type on the warp,
    // then each on the weft (yarnOfType()).
    const Yarn& yarn(int index) const { return yarns_[size_t(index)]; }
    // Its lobe without the colour (exponents, R_s and their roots), precomputed per yarn.
    const LobeShape& lobeShape(int index) const { return shapes_[size_t(index)]; }
    int yarnCount() const { return int(yarns_.size()); }
    static int yarnOfType(int type, YarnSide side, int typeCount) {
        return 2 + type + (side == YarnSide::Weft ? typeCount : 0);
    }
    // The parts of a weave that are cheap to build alone (the preview rebuilds them as sliders move).
    static std::vector<Yarn> resolvedYarns(const WovenParams& p);
    static ThreadLayout threads(const WovenParams& p, YarnSide side);  // Warp or Weft

    // A position e (weave elements, uv x repeat) moved by whole repeats of everything a lookup
    // reads into (-R, R): R in [2^61, 2^62] is a multiple of the tile, the thread layout and
    // 2^32 threads along each axis (the noise seeds wrap to 32 bits). Huge uvs then keep 64-bit
    // thread indices from overflowing, while fmod's exact remainder leaves the point's place in
    // its thread and every seed as they were; positions inside (-R, R) are returned as given.
    glm::dvec2 wrapped(glm::dvec2 e) const {
        if (std::fabs(e.x) >= wrap_.x) e.x = std::fmod(e.x, wrap_.x);
        if (std::fabs(e.y) >= wrap_.y) e.y = std::fmod(e.y, wrap_.y);
        return e;
    }

private:
    WeavePattern front_, back_;
    std::unique_ptr<const WeaveFloats> floats_;
    std::vector<Yarn> yarns_;
    std::vector<LobeShape> shapes_;
    ThreadLayout warp_, weft_;
    glm::dvec2 wrap_;  // R along u and v
};

// The distinct yarns the threads of `side` (Warp or Weft) use: the side's own yarn, or the
// yarn types its list names, resolved on that side.
std::vector<Yarn> usedYarns(const WovenParams& p, YarnSide side);
// Gaps between yarns exist only where both crossing yarns are narrower than their cells.
bool mayShowGaps(const WovenParams& p);
// Whether light may pass the cloth between its yarns: gaps, and no backing behind them.
bool mayBeSeenThrough(const WovenParams& p);
// Whether any thread's yarn has colour noise.
bool hasNoise(const WovenParams& p);

}  // namespace woven
