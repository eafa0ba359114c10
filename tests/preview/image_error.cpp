#include "image_error.h"

#include <algorithm>
#include <cmath>

namespace woven::test {

namespace {
double l1(const glm::vec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }
}  // namespace

ImageError relativeError(const Image& a, const Image& reference, const std::vector<uint8_t>& mask) {
    double meanRef = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < reference.pixels.size(); ++i)
        if (mask[i]) { meanRef += l1(reference.pixels[i]); ++n; }
    ImageError e;
    if (n == 0) return e;
    const double floor = 0.02 * meanRef / double(n);
    std::vector<double> errors;
    errors.reserve(n);
    for (size_t i = 0; i < reference.pixels.size(); ++i)
        if (mask[i]) errors.push_back(l1(a.pixels[i] - reference.pixels[i]) / (l1(reference.pixels[i]) + floor));
    for (double x : errors) e.mean += x;
    e.mean /= double(n);
    std::sort(errors.begin(), errors.end());
    e.p99 = errors[std::min(errors.size() - 1, size_t(0.99 * double(errors.size())))];
    e.pixels = n;
    return e;
}

}  // namespace woven::test
