#include "render_passes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "luminance.h"

namespace woven {

PassSums& PassSums::operator+=(const PassSums& other) {
    for (int c = 0; c < 3; ++c) {
        albedo[c] += other.albedo[c];
        normal[c] += other.normal[c];
        direct[c] += other.direct[c];
        square[c] += other.square[c];
    }
    depth += other.depth;
    directSquare += other.directSquare;
    return *this;
}

bool PassSums::operator==(const PassSums& other) const {
    for (int c = 0; c < 3; ++c)
        if (albedo[c] != other.albedo[c] || normal[c] != other.normal[c] || direct[c] != other.direct[c] ||
            square[c] != other.square[c])
            return false;
    return depth == other.depth && directSquare == other.directSquare;
}

namespace {

// From n >= 2 samples' sum and sum of squares: (sum x^2 - (sum x)^2 / n) / (n - 1) is one
// sample's variance; the mean's is 1/n of it.
float varianceOfMean(double sum, double squares, float n) {
    const double spread = std::max(0.0, squares - sum * sum / double(n));
    return float(spread / (double(n) - 1.0) / double(n));
}

}  // namespace

RenderPasses meanPasses(int width, int height, const std::vector<float>& count,
                        const std::vector<ExactSum>& radianceSums, const std::vector<PassSums>& sums) {
    const size_t pixels = size_t(width) * size_t(height);
    if (count.size() != pixels || radianceSums.size() != 3 * pixels || sums.size() != pixels)
        throw std::invalid_argument("render passes: the sample counts, radiance sums and pass sums do not match the frame");
    RenderPasses p;
    for (Image* image : {&p.albedo, &p.normal, &p.direct, &p.directVariance, &p.variance}) {
        image->width = width;
        image->height = height;
        image->pixels.resize(pixels);
    }
    p.depth.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        const PassSums& s = sums[i];
        const float n = count[i];
        glm::vec3 normal(0.0f);
        for (int c = 0; c < 3; ++c) {
            p.albedo.pixels[i][c] = s.albedo[c].mean(n);
            p.direct.pixels[i][c] = s.direct[c].mean(n);
            normal[c] = s.normal[c].mean(n);
            if (n >= 2.0f) {
                p.variance.pixels[i][c] = varianceOfMean(radianceSums[3 * i + size_t(c)].value(), s.square[c].value(), n);
            }
        }
        const float length = glm::length(normal);
        p.normal.pixels[i] = length > 0.0f ? normal / length : normal;
        p.depth[i] = s.depth.mean(n);
        const float y = luminance(p.direct.pixels[i]);
        if (n >= 2.0f && y > 0.0f) {
            // The luminance's sum from the channels' sums, as each sample's is from its own.
            const glm::dvec3 sums(s.direct[0].value(), s.direct[1].value(), s.direct[2].value());
            const float variance = varianceOfMean(luminance(sums), s.directSquare.value(), n);
            for (int c = 0; c < 3; ++c) {
                const float share = p.direct.pixels[i][c] / y;
                p.directVariance.pixels[i][c] = variance * share * share;
            }
        }
    }
    return p;
}

}  // namespace woven
