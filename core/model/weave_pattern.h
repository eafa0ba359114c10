#pragma once
// Which yarn lies on top in each weave element (MODEL.md section 1), as a periodic binary
// tile, with the float (run of consecutive top elements of one yarn) each cell belongs to.
// The regular (i, j, k) family and hand-drawn tiles share this one representation.
#include <cstdint>
#include <string>
#include <vector>

#include "woven_params.h"

namespace woven {

enum class YarnType : uint8_t { Weft = 0, Warp = 1, Gap = 2 };

class WeavePattern {
public:
    // Tile of the regular family: d = (U + k V) mod (i + j); d < i -> weft.
    static WeavePattern regular(int i, int j, int k);
    // Rows of '-' (weft) and '|' (warp), row V = 0 first.
    static WeavePattern fromRows(const std::vector<std::string>& rows);
    static WeavePattern fromParams(const WovenParams& p);

    int width() const { return width_; }    // P_u
    int height() const { return height_; }  // P_v

    // Top yarn of element (U, V), any integers (periodic).
    YarnType top(int64_t U, int64_t V) const { return YarnType(warp_[cellIndex(U, V)]); }

    // The float through element (U, V) of the yarn of type `yarn` (which must be the top yarn
    // there): `position` = elements before this one in the float, `length` = elements in it.
    // A yarn that is on top along its whole tile period has length = the period.
    struct Float { int position, length; };
    Float floatAt(int64_t U, int64_t V) const { return floats_[cellIndex(U, V)]; }

    // The same fabric seen from its back: warp and weft swap places on top.
    WeavePattern reversed() const;

    // MODEL.md's drawing: one line per row V from 0, '-' weft, '|' warp, U from 0.
    std::string draw(int columns, int rows) const;

private:
    WeavePattern(int width, int height, std::vector<uint8_t> warp);
    size_t cellIndex(int64_t U, int64_t V) const;
    void computeFloats();

    int width_ = 1, height_ = 1;
    std::vector<uint8_t> warp_;  // 1 where warp is on top, row-major, width_ x height_
    std::vector<Float> floats_;
};

}  // namespace woven
