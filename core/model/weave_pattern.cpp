#include "weave_pattern.h"

#include <numeric>
#include <stdexcept>

namespace woven {

namespace {
int64_t positiveMod(int64_t a, int64_t m) {
    int64_t r = a % m;
    return r < 0 ? r + m : r;
}
}  // namespace

WeavePattern::WeavePattern(int width, int height, std::vector<uint8_t> warp)
    : width_(width), height_(height), warp_(std::move(warp)) {
    computeFloats();
}

WeavePattern WeavePattern::regular(int i, int j, int k) {
    if (i < 0 || j < 0 || i + j < 1) throw std::invalid_argument("weave (i, j, k) needs i, j >= 0 and i + j >= 1");
    const int period = i + j;
    const int64_t shift = positiveMod(k, period);
    const int rows = period / std::gcd(int(shift), period);  // gcd(0, n) = n -> one row
    std::vector<uint8_t> warp(size_t(period) * rows);
    for (int V = 0; V < rows; ++V)
        for (int U = 0; U < period; ++U)
            warp[size_t(V) * period + U] = positiveMod(U + shift * V, period) >= i;
    return WeavePattern(period, rows, std::move(warp));
}

WeavePattern WeavePattern::fromRows(const std::vector<std::string>& rows) {
    if (rows.empty() || rows[0].empty()) throw std::invalid_argument("weave tile is empty");
    const int width = int(rows[0].size()), height = int(rows.size());
    std::vector<uint8_t> warp(size_t(width) * height);
    for (int V = 0; V < height; ++V) {
        if (int(rows[V].size()) != width) throw std::invalid_argument("weave tile rows differ in length");
        for (int U = 0; U < width; ++U) {
            char c = rows[V][U];
            if (c != '-' && c != '|') throw std::invalid_argument("weave tile uses '-' and '|' only");
            warp[size_t(V) * width + U] = c == '|';
        }
    }
    return WeavePattern(width, height, std::move(warp));
}

WeavePattern WeavePattern::fromParams(const WovenParams& p) {
    return p.tile.empty() ? regular(p.pattern.x, p.pattern.y, p.pattern.z) : fromRows(p.tile);
}

WeavePattern WeavePattern::reversed() const {
    std::vector<uint8_t> flipped(warp_.size());
    for (size_t c = 0; c < warp_.size(); ++c) flipped[c] = !warp_[c];
    return WeavePattern(width_, height_, std::move(flipped));
}

size_t WeavePattern::cellIndex(int64_t U, int64_t V) const {
    return size_t(positiveMod(V, height_)) * width_ + size_t(positiveMod(U, width_));
}

void WeavePattern::computeFloats() {
    floats_.assign(warp_.size(), Float{0, 1});
    // A weft float runs along U within a row; a warp float runs along V within a column.
    // Walk each line of the tile cyclically from a cell where the top yarn changes.
    auto walk = [&](int lineLength, auto cellOf) {
        int start = -1;
        for (int a = 0; a < lineLength; ++a)
            if (warp_[cellOf(a)] != warp_[cellOf((a + lineLength - 1) % lineLength)]) { start = a; break; }
        if (start < 0) {  // one yarn on top along the whole line
            for (int a = 0; a < lineLength; ++a) floats_[cellOf(a)] = Float{a, lineLength};
            return;
        }
        int runStart = 0;
        for (int step = 1; step <= lineLength; ++step) {
            int a = (start + step) % lineLength;
            if (step == lineLength || warp_[cellOf(a)] != warp_[cellOf(start + runStart)]) {
                int length = step - runStart;
                for (int q = 0; q < length; ++q) floats_[cellOf((start + runStart + q) % lineLength)] = Float{q, length};
                runStart = step;
            }
        }
    };
    for (int V = 0; V < height_; ++V) {  // weft floats
        walk(width_, [&](int U) { return size_t(V) * width_ + size_t(U % width_); });
    }
    std::vector<Float> weftFloats = floats_;
    for (int U = 0; U < width_; ++U) {  // warp floats
        walk(height_, [&](int V) { return size_t(V % height_) * width_ + size_t(U); });
    }
    // Each cell keeps the float of the yarn that is on top there.
    for (size_t c = 0; c < warp_.size(); ++c)
        if (!warp_[c]) floats_[c] = weftFloats[c];
}

std::string WeavePattern::draw(int columns, int rows) const {
    std::string out;
    for (int V = 0; V < rows; ++V) {
        for (int U = 0; U < columns; ++U) out += top(U, V) == YarnType::Warp ? '|' : '-';
        out += '\n';
    }
    return out;
}

}  // namespace woven
