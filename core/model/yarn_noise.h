#pragma once
// Per-yarn Perlin noise (MODEL.md section 4): smooth along one yarn, independent between yarns.
// Only 32-bit integer operations, so shaders/ can evaluate the identical function in GLSL.
#include <cstdint>

namespace woven {

// A 32-bit integer hash (the "lowbias32" finaliser by C. Wellons).
inline uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// 1D gradient noise in about [-1, 1] with gradients hashed from (lattice point, seed). Each
// seed is an independent noise function; the seed also shifts the lattice so that yarns do not
// share their zero crossings.
float yarnNoise(double along, uint32_t seed);

}  // namespace woven
