#include "thread_layout.h"

#include <algorithm>
#include <numeric>

namespace woven {

ThreadLayout::ThreadLayout(const std::vector<glm::vec3>& colors, const std::vector<int>& yarns,
                           const std::vector<float>& spacing, const glm::vec3& color, int defaultYarn,
                           int firstTypeYarn) {
    size_t period = 1;
    for (size_t n : {colors.size(), yarns.size(), spacing.size()})
        if (n > 0) period = std::lcm(period, n);
    period_ = int(period);  // validate() keeps it within kMaxThreadPeriod
    colors_.resize(period, color);
    yarns_.resize(period, defaultYarn);
    for (size_t k = 0; k < period; ++k) {
        if (!colors.empty()) colors_[k] = colors[k % colors.size()];
        if (!yarns.empty()) yarns_[k] = firstTypeYarn + yarns[k % yarns.size()];
    }
    const bool even =
        spacing.empty() || std::all_of(spacing.begin(), spacing.end(), [&](float s) { return s == spacing[0]; });
    if (even) {  // locate() is a floor
        integrateColors();
        return;
    }

    // Cells scaled so that the period spans `period` mean thread widths, as `repeat` counts.
    double total = 0.0;
    for (size_t k = 0; k < period; ++k) total += spacing[k % spacing.size()];
    start_.resize(period);
    width_.resize(period);
    inverseWidth_.resize(period);
    double sum = 0.0;
    for (size_t k = 0; k < period; ++k) {
        start_[k] = double(period) * sum / total;
        sum += spacing[k % spacing.size()];
        width_[k] = double(period) * sum / total - start_[k];
        inverseWidth_[k] = 1.0 / width_[k];
    }
    inversePeriod_ = 1.0 / double(period);
    belowPeriod_ = std::nextafter(double(period), 0.0);
    firstInInterval_.resize(period);
    int slot = 0;
    for (int b = 0; b < period_; ++b) {
        while (slot + 1 < period_ && start_[size_t(slot) + 1] <= double(b)) ++slot;
        firstInInterval_[size_t(b)] = slot;
    }
    integrateColors();
}

void ThreadLayout::integrateColors() {
    colorSum_.assign(size_t(period_) + 1, glm::dvec3(0.0));
    for (int k = 0; k < period_; ++k)
        colorSum_[size_t(k) + 1] = colorSum_[size_t(k)] + glm::dvec3(colors_[size_t(k)]) * (spaced() ? width(k) : 1.0);
}

glm::dvec3 ThreadLayout::integratedColor(double e) const {
    const Cell c = locate(e);
    const double width = spaced() ? this->width(c.slot) : 1.0;
    const double periods = double((c.thread - c.slot) / period_);  // exact: thread - slot is a multiple of the period
    return periods * colorSum_[size_t(period_)] + colorSum_[size_t(c.slot)] +
           glm::dvec3(colors_[size_t(c.slot)]) * (c.across * width);
}

glm::vec3 ThreadLayout::meanColor(double e0, double e1) const {
    if (period_ == 1) return colors_[0];
    if (!(e1 - e0 > 1e-9)) return colors_[size_t(locate(e0).slot)];
    return glm::vec3((integratedColor(e1) - integratedColor(e0)) / (e1 - e0));
}

ThreadLayout::Cell ThreadLayout::locateSpaced(double e) const {
    const double n = double(period_);
    const double q = std::floor(e * inversePeriod_);
    // r in [0, n): the position in the period (rounding can put e - q n a hair outside).
    const double r = std::clamp(e - q * n, 0.0, belowPeriod_);
    const int b = int(r);
    const int lo = firstInInterval_[size_t(b)];
    const int hi = b + 1 < period_ ? firstInInterval_[size_t(b) + 1] : period_ - 1;
    // The last slot in [lo, hi] that starts at or before r: usually lo itself or the next, so
    // a short walk, and a binary search where threads far thinner than the mean crowd.
    int slot = lo;
    if (hi - lo <= 8) {
        while (slot < hi && start_[size_t(slot) + 1] <= r) ++slot;
    } else {
        slot = int(std::upper_bound(start_.begin() + lo + 1, start_.begin() + hi + 1, r) - start_.begin()) - 1;
    }
    const double across = std::clamp((r - start_[size_t(slot)]) * inverseWidth_[size_t(slot)], 0.0, kBelowOne);
    return {int64_t(q) * period_ + slot, across, slot};
}

}  // namespace woven
