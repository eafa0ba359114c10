#include "weave_pattern.h"

#include <numeric>
#include <stdexcept>

namespace woven {

WeavePattern::WeavePattern(int width, int height, std::shared_ptr<const std::vector<uint64_t>> bits, bool reversed)
    : width_(width), height_(height), wordsPerRow_((width + 63) / 64), bits_(std::move(bits)), reversed_(reversed) {}

template <class IsWarp>
WeavePattern WeavePattern::build(int width, int height, IsWarp isWarp) {
    const size_t wordsPerRow = size_t(width + 63) / 64;
    auto bits = std::make_shared<std::vector<uint64_t>>(wordsPerRow * size_t(height), 0);
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u)
            if (isWarp(u, v)) (*bits)[size_t(v) * wordsPerRow + size_t(u >> 6)] |= uint64_t(1) << (u & 63);
    return WeavePattern(width, height, std::move(bits), false);
}

WeavePattern WeavePattern::regular(int i, int j, int k) {
    if (i < 0 || j < 0 || i + j < 1) throw std::invalid_argument("weave (i, j, k) needs i, j >= 0 and i + j >= 1");
    const int period = i + j;
    const int64_t shift = positiveMod(k, period);
    const int rows = period / std::gcd(int(shift), period);  // gcd(0, n) = n -> one row
    return build(period, rows, [&](int U, int V) { return positiveMod(U + shift * V, period) >= i; });
}

WeavePattern WeavePattern::fromRows(const std::vector<std::string>& rows) {
    if (rows.empty() || rows[0].empty()) throw std::invalid_argument("weave tile is empty");
    const int width = int(rows[0].size()), height = int(rows.size());
    for (const std::string& row : rows) {
        if (int(row.size()) != width) throw std::invalid_argument("weave tile rows differ in length");
        for (char c : row)
            if (c != '-' && c != '|') throw std::invalid_argument("weave tile uses '-' and '|' only");
    }
    return build(width, height, [&](int U, int V) { return rows[size_t(V)][size_t(U)] == '|'; });
}

WeavePattern WeavePattern::fromParams(const WovenParams& p) {
    return p.tile.empty() ? regular(p.pattern.x, p.pattern.y, p.pattern.z) : fromRows(p.tile);
}

WeavePattern WeavePattern::reversed() const { return WeavePattern(width_, height_, bits_, !reversed_); }

std::string WeavePattern::draw(int columns, int rows) const {
    std::string out;
    for (int V = 0; V < rows; ++V) {
        for (int U = 0; U < columns; ++U) out += top(U, V) == YarnType::Warp ? '|' : '-';
        out += '\n';
    }
    return out;
}

namespace {

// The runs of equal values along a cyclic line of `length` cells: for each cell, the cells
// before it in its run and the run's length. A line of one value is one run of the whole
// length, counted from cell 0.
template <class ValueAt, class Store>
void cyclicRuns(int length, ValueAt valueAt, Store store) {
    int start = -1;  // a cell where the value changes from the cell before
    for (int a = 0; a < length && start < 0; ++a)
        if (valueAt(a) != valueAt((a + length - 1) % length)) start = a;
    if (start < 0) {
        for (int a = 0; a < length; ++a) store(a, a, length);
        return;
    }
    int runStart = 0;
    for (int step = 1; step <= length; ++step) {
        if (step < length && valueAt((start + step) % length) == valueAt((start + runStart) % length)) continue;
        const int runLength = step - runStart;
        for (int q = 0; q < runLength; ++q) store((start + runStart + q) % length, q, runLength);
        runStart = step;
    }
}

}  // namespace

WeaveFloats::WeaveFloats(const WeavePattern& pattern)
    : width_(pattern.width()), height_(pattern.height()), runs_(size_t(width_) * size_t(height_)) {
    // Lengths are stored less one: a run of the full 65536 fits 16 bits (kMaxTileSide is less).
    for (int v = 0; v < height_; ++v)
        cyclicRuns(width_, [&](int u) { return pattern.topInTile(u, v); }, [&](int u, int position, int length) {
            Runs& r = runs_[size_t(v) * size_t(width_) + size_t(u)];
            r.rowPosition = uint16_t(position);
            r.rowLength = uint16_t(length - 1);
        });
    for (int u = 0; u < width_; ++u)
        cyclicRuns(height_, [&](int v) { return pattern.topInTile(u, v); }, [&](int v, int position, int length) {
            Runs& r = runs_[size_t(v) * size_t(width_) + size_t(u)];
            r.columnPosition = uint16_t(position);
            r.columnLength = uint16_t(length - 1);
        });
}

}  // namespace woven
