#include "weave_construction.h"

#include <numeric>
#include <set>
#include <vector>

namespace woven {

namespace {

bool isPlain(const WeavePattern& p) {
    for (int v = 0; v < p.height(); ++v)
        for (int u = 0; u < p.width(); ++u)
            if (p.top(u, v) == p.top(u + 1, v) || p.top(u, v) == p.top(u, v + 1)) return false;
    return true;
}

// The shift s (0 < s < width) with top(U, V + 1) = top(U + s, V) everywhere, or 0 for none.
int rowShift(const WeavePattern& p) {
    for (int s = 1; s < p.width(); ++s) {
        bool all = true;
        for (int v = 0; v < p.height() && all; ++v)
            for (int u = 0; u < p.width() && all; ++u) all = p.top(u, v + 1) == p.top(u + s, v);
        if (all) return s;
    }
    return 0;
}

// The smallest period of the weave along a row, which a tile drawn twice over may hide.
int rowPeriod(const WeavePattern& p) {
    for (int period = 1; period < p.width(); ++period) {
        if (p.width() % period) continue;
        bool all = true;
        for (int v = 0; v < p.height() && all; ++v)
            for (int u = 0; u < p.width() && all; ++u) all = p.top(u, v) == p.top(u + period, v);
        if (all) return period;
    }
    return p.width();
}

// Whether each row holds the minority yarn on one cell only.
bool oneInterlacingARow(const WeavePattern& p, int period) {
    for (int v = 0; v < p.height(); ++v) {
        int warp = 0;
        for (int u = 0; u < period; ++u) warp += p.top(u, v) == YarnType::Warp;
        if (warp != 1 && warp != period - 1) return false;
    }
    return true;
}

int distinctEnds(const WeavePattern& p) {
    std::set<std::vector<bool>> ends;
    for (int u = 0; u < p.width(); ++u) {
        std::vector<bool> column(size_t(p.height()));
        for (int v = 0; v < p.height(); ++v) column[size_t(v)] = p.top(u, v) == YarnType::Warp;
        ends.insert(column);
    }
    return int(ends.size());
}

}  // namespace

Construction construction(const WeavePattern& face) {
    if (isPlain(face)) return Construction::Plain;
    const int period = rowPeriod(face);
    const int shift = rowShift(face) % period;
    if (shift != 0 && period >= 3) {
        // Row V + 1 is row V moved by -shift: a feature at U goes to U - shift one row down, and
        // with rows drawn downwards a move to the left going down is a diagonal rising to the right.
        if (shift == 1) return Construction::TwillRight;
        if (shift == period - 1) return Construction::TwillLeft;
        if (period >= 5 && std::gcd(shift, period) == 1 && oneInterlacingARow(face, period)) return Construction::Satin;
    }
    return distinctEnds(face) <= kDobbyShafts ? Construction::Dobby : Construction::Jacquard;
}

const char* u3mConstructionName(Construction c) {
    switch (c) {
        case Construction::Plain: return "Plain weave";
        case Construction::TwillLeft: return "Twill - left hand (S)";
        case Construction::TwillRight: return "Twill - right hand (Z)";
        case Construction::Satin: return "Satin";
        case Construction::Dobby: return "Dobby";
        case Construction::Jacquard: return "Jacquard";
    }
    return "Dobby";
}

}  // namespace woven
