#include "yarn_noise.h"

#include <cmath>

#include "sampling.h"

namespace woven {

namespace {
float gradient(int64_t lattice, uint64_t seed) {
    return float(mix64(uint64_t(lattice) * 0x9e3779b97f4a7c15ULL ^ seed) >> 40) * 0x1p-23f - 1.0f;
}
}  // namespace

float yarnNoise(double along, uint64_t seed) {
    const uint64_t key = mix64(seed + 0x5851f42d4c957f2dULL);
    const double x = along + double(key >> 40) * 0x1p-24;  // per-yarn lattice offset in [0, 1)
    const double cell = std::floor(x);
    const float f = float(x - cell);
    const int64_t i = int64_t(cell);
    const float fade = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
    const float a = gradient(i, key) * f, b = gradient(i + 1, key) * (f - 1.0f);
    return 2.0f * (a + fade * (b - a));  // 1D Perlin lies in [-0.5, 0.5]
}

}  // namespace woven
