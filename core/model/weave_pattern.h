#pragma once
// Which yarn lies on top in each weave element (MODEL.md section 1), as a periodic binary tile.
// The regular (i, j, k) family, hand-drawn tiles and drafts share this one representation: one
// bit per cell, so a tile of 1024 x 1024 threads takes 128 KiB and a lookup costs the same for
// any tile. The floats the crimp needs are a separate table (WeaveFloats), built only for
// materials with crimp.
#include <cstdint>
#include <memory>
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
    YarnType top(int64_t U, int64_t V) const {
        return topInTile(int(positiveMod(U, width_)), int(positiveMod(V, height_)));
    }
    // Top yarn of the tile's cell (u, v), 0 <= u < width(), 0 <= v < height().
    YarnType topInTile(int u, int v) const {
        const uint64_t word = (*bits_)[size_t(v) * size_t(wordsPerRow_) + size_t(u >> 6)];
        return YarnType(((word >> (u & 63)) & 1U) ^ uint64_t(reversed_));
    }

    // A float: a run of consecutive elements with the same yarn on top. `position` = elements
    // before this one in the float, `length` = elements in it. A yarn that is on top along its
    // whole tile period has length = the period.
    struct Float { int position, length; };

    // The same fabric seen from its back: warp and weft swap places on top. Shares the bits.
    WeavePattern reversed() const;

    // MODEL.md's drawing: one line per row V from 0, '-' weft, '|' warp, U from 0.
    std::string draw(int columns, int rows) const;

    static int64_t positiveMod(int64_t a, int64_t m) {
        const int64_t r = a % m;
        return r < 0 ? r + m : r;
    }

private:
    WeavePattern(int width, int height, std::shared_ptr<const std::vector<uint64_t>> bits, bool reversed);
    template <class IsWarp>
    static WeavePattern build(int width, int height, IsWarp isWarp);

    int width_ = 1, height_ = 1, wordsPerRow_ = 1;
    std::shared_ptr<const std::vector<uint64_t>> bits_;  // bit u of row v: warp on top (front face)
    bool reversed_ = false;
};

// The float through every cell of a tile, along its row (the weft's float where the weft is on
// top) and along its column (the warp's): for the crimp, which bends a yarn along its float.
// Eight bytes a cell, and the same table for both faces, since a run of equal cells is a run on
// either face.
class WeaveFloats {
public:
    explicit WeaveFloats(const WeavePattern& pattern);

    // The float of `yarn` (Weft: along the row, Warp: along the column) through element (U, V);
    // `yarn` must be the top yarn there on the face being shaded.
    WeavePattern::Float at(int64_t U, int64_t V, YarnType yarn) const {
        const Runs& r = runs_[size_t(WeavePattern::positiveMod(V, height_)) * size_t(width_) +
                              size_t(WeavePattern::positiveMod(U, width_))];
        return yarn == YarnType::Weft ? WeavePattern::Float{r.rowPosition, int(r.rowLength) + 1}
                                      : WeavePattern::Float{r.columnPosition, int(r.columnLength) + 1};
    }

    // The table as the GPU takes it: per cell, row position, row length - 1, column position,
    // column length - 1.
    struct Runs { uint16_t rowPosition, rowLength, columnPosition, columnLength; };
    const std::vector<Runs>& runs() const { return runs_; }

private:
    int width_, height_;
    std::vector<Runs> runs_;
};

}  // namespace woven
