#pragma once
// The threads of one side of the cloth (the warp ends across u, or the weft picks across v) as
// MODEL.md section 6 lays them out: a sequence of threads that repeats, each with a colour, a
// yarn and a width (its spacing). The material's lists for that side are expanded to the period
// they repeat together. Finding the thread at a point costs the same for any period: evenly
// spaced threads are a floor; spaced ones a lookup of the unit interval the point falls in,
// then a binary search among the few threads that start inside it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "weave_pattern.h"

namespace woven {

class ThreadLayout {
public:
    // `colors`, `yarns`, `spacing`: the side's lists (WovenParams::warp_colors, ...; each empty
    // or repeating). Threads the lists leave out take `color` and yarn `defaultYarn`; yarn type
    // t of `yarns` is yarn `firstTypeYarn + t` (indices into the material's resolved yarns).
    ThreadLayout(const std::vector<glm::vec3>& colors, const std::vector<int>& yarns, const std::vector<float>& spacing,
                 const glm::vec3& color, int defaultYarn, int firstTypeYarn);

    // The thread at a point. `thread`: its index (any integer: end U or pick V); `across`: the
    // position across its cell in [0, 1); `slot`: its place in the period (thread mod period).
    struct Cell {
        int64_t thread;
        double across;
        int slot;
    };
    // `e`: the position in mean thread widths (uv times `repeat`).
    Cell locate(double e) const {
        if (!spaced()) {
            const double f = std::floor(e);
            const int64_t thread = int64_t(f);
            return {thread, std::min(e - f, kBelowOne), period_ == 1 ? 0 : int(WeavePattern::positiveMod(thread, period_))};
        }
        return locateSpaced(e);
    }

    // The mean colour over [e0, e1] (mean thread widths, e0 < e1), each thread weighted by how much
    // of its cell the interval covers: the weave filter's colour over a pixel's footprint.
    glm::vec3 meanColor(double e0, double e1) const;

    int period() const { return period_; }
    const glm::vec3& color(int slot) const { return colors_[size_t(slot)]; }
    int yarn(int slot) const { return yarns_[size_t(slot)]; }

    // Spacing: whether threads differ in width. Then slot k's cell starts at start(k) and is
    // width(k) wide (mean thread widths from the period's start, width 1 on average), and the
    // unit interval [b, b + 1) begins in the cell of slot firstInInterval(b).
    bool spaced() const { return !start_.empty(); }
    double start(int slot) const { return start_[size_t(slot)]; }
    double width(int slot) const { return width_[size_t(slot)]; }
    int firstInInterval(int b) const { return firstInInterval_[size_t(b)]; }

private:
    static constexpr double kBelowOne = 1.0 - 1e-12;  // keeps `across` below 1 where e rounds up
    Cell locateSpaced(double e) const;
    void integrateColors();

    int period_ = 1;
    std::vector<glm::vec3> colors_;  // per slot
    std::vector<int> yarns_;         // per slot
    std::vector<double> start_, width_, inverseWidth_;
    double inversePeriod_ = 1.0, belowPeriod_ = 0.0;
    std::vector<int> firstInInterval_;
    std::vector<glm::dvec3> colorSum_;  // colour x cell width summed over the slots before each, period + 1 entries

    glm::dvec3 integratedColor(double e) const;  // the colour integrated from 0 to e
};

}  // namespace woven
