#pragma once
// Per-yarn Perlin noise (MODEL.md section 4): smooth along one yarn, independent between yarns.
#include <cstdint>

namespace woven {

// 1D gradient noise in about [-1, 1] with gradients hashed from (lattice point, seed). Each
// seed is an independent noise function; the seed also shifts the lattice so that yarns do not
// share their zero crossings.
float yarnNoise(double along, uint64_t seed);

}  // namespace woven
