#include "yarn_noise.h"

#include <cmath>

namespace woven {

namespace {
float gradient(uint32_t lattice, uint32_t key) {
    return float(hash32(lattice ^ key) >> 8) * 0x1p-23f - 1.0f;  // [-1, 1)
}
}  // namespace

float yarnNoise(double along, uint32_t seed) {
    const uint32_t key = hash32(seed + 0x9e3779b9U);
    const double x = along + double(key >> 8) * 0x1p-24;  // per-yarn lattice offset in [0, 1)
    const double cell = std::floor(x);
    const float f = float(x - cell);
    const uint32_t i = uint32_t(int64_t(cell));  // wraps like a GLSL int -> uint conversion
    const float fade = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
    const float a = gradient(i, key) * f, b = gradient(i + 1U, key) * (f - 1.0f);
    return 2.0f * (a + fade * (b - a));  // 1D Perlin lies in [-0.5, 0.5]
}

}  // namespace woven
