#pragma once
// Owen-scrambled Sobol points (Burley 2020, "Practical Hash-based Owen Scrambling"): every
// dimension pair is the first two Sobol dimensions, its sample index shuffled and its values
// scrambled by hash-based nested uniform permutations keyed by (seed, pixel, dimension). The
// first 2^k samples of a pixel are then stratified over the 2^k elementary intervals of each
// pair, while pairs and pixels stay independent of one another.
#include <cstdint>

#include <glm/vec2.hpp>

namespace woven {

class SobolSampler {
public:
    // sampleIndex is 64-bit: each block of 2^32 samples gets its own scrambling, as the
    // 32-bit points repeat after 2^32.
    SobolSampler(uint64_t seed, uint64_t pixel, uint64_t sampleIndex);

    float get1D(uint32_t dimension) const;
    glm::vec2 get2D(uint32_t dimension) const;

private:
    uint64_t dimensionKey(uint32_t dimension) const;

    uint64_t key_;     // of (seed, pixel, sample block)
    uint32_t reversedIndex_;  // the sample's index within its block, its bits reversed
};

// A nested uniform (Owen) scrambling of a 32-bit fixed-point fraction: each bit is flipped by a
// hash of the bits above it and the seed. Also shuffles sample indices, whose aligned blocks of
// 2^k it maps onto aligned blocks of 2^k.
uint32_t owenScramble(uint32_t v, uint32_t seed);

}  // namespace woven
