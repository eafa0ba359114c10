#pragma once
// Goodness of fit for the sampling tests.
#include <cmath>
#include <vector>

namespace woven::test {

// Pearson's chi-square of observed counts against expected counts, bins with an expected count
// under 5 pooled into one, turned into a standard normal score by the Wilson-Hilferty cube-root
// approximation. A sampler that matches its density gives |z| of order 1; the tests reject at
// z > 4 (a false alarm about once in 30,000 seeds, and the seeds are fixed), while a density off
// by a few per cent in any sizeable region gives z in the tens or hundreds at these sample counts.
inline double chiSquareZ(const std::vector<double>& observed, const std::vector<double>& expected) {
    double chi2 = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
    int bins = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++bins;
    }
    if (pooledExpected > 0.0) {
        chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++bins;
    } else if (pooledObserved > 0.0) {
        return 1e9;  // samples where the density says there can be none
    }
    const double k = bins - 1;  // degrees of freedom: the total is fixed
    if (k < 1) return 0.0;
    return (std::cbrt(chi2 / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
}

}  // namespace woven::test
