#include "sobol_sampler.h"

#include "sampling.h"

namespace woven {

namespace {

constexpr uint32_t reverseBits(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// Sobol's second dimension (primitive polynomial x + 1, m_1 = 1 in Joe and Kuo's table): its
// direction numbers follow v_k = v_{k-1} ^ (v_{k-1} >> 1), the Pascal matrix mod 2. The first
// dimension is the van der Corput sequence, reverseBits(). The matrix is applied a byte of the
// index at a time, from the XORs of its columns for each byte value: a sample costs four loads,
// not a loop over 32 bits, which in a small scene cost as much as the rays. The tables hold the
// columns bit-reversed, as the scrambling wants them (permuteReversed()).
struct SecondDimensionTables {
    uint32_t byByte[4][256];
};
constexpr SecondDimensionTables secondDimensionTables() {
    uint32_t v[32] = {};
    v[0] = 0x80000000u;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    SecondDimensionTables t{};
    for (int b = 0; b < 4; ++b)
        for (int value = 0; value < 256; ++value) {
            uint32_t x = 0;
            for (int k = 0; k < 8; ++k)
                if (value & (1 << k)) x ^= v[8 * b + k];
            t.byByte[b][value] = reverseBits(x);
        }
    return t;
}
constexpr SecondDimensionTables kSecondDimension = secondDimensionTables();

// reverseBits() of Sobol's second dimension at `index`.
uint32_t sobolSecondDimensionReversed(uint32_t index) {
    return kSecondDimension.byByte[0][index & 0xffu] ^ kSecondDimension.byByte[1][(index >> 8) & 0xffu] ^
           kSecondDimension.byByte[2][(index >> 16) & 0xffu] ^ kSecondDimension.byByte[3][index >> 24];
}

// Laine and Karras's permutation with Vegard Nossum's constants, as pbrt-v4's
// FastOwenScrambler, of bit-reversed values: additions and multiplications by even constants
// only carry upwards, so each original bit depends on the bits above it alone. The sampler
// keeps its values reversed between scramblings, which saves two of owenScramble()'s
// reversals each.
uint32_t permuteReversed(uint32_t v, uint32_t seed) {
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return v;
}

float toUnit(uint32_t x) { return float(x >> 8) * 0x1p-24f; }  // [0, 1), as Rng::uniform()

}  // namespace

uint32_t owenScramble(uint32_t v, uint32_t seed) { return reverseBits(permuteReversed(reverseBits(v), seed)); }

SobolSampler::SobolSampler(uint64_t seed, uint64_t pixel, uint64_t sampleIndex)
    : key_(mix64(seed ^ mix64(pixel * 0x9e3779b97f4a7c15ULL ^ mix64((sampleIndex >> 32) + 0x2545f4914f6cdd1dULL)))),
      reversedIndex_(reverseBits(uint32_t(sampleIndex))) {}

// mix64(dimension + 1) of the dimensions a path of up to about twenty bounces draws, tabulated:
// the key of a dimension is then one hash of the sample's key, not two.
constexpr uint32_t kTabulatedDimensions = 512;
struct DimensionHashes {
    uint64_t of[kTabulatedDimensions];
};
constexpr DimensionHashes dimensionHashes() {
    DimensionHashes h{};
    for (uint32_t d = 0; d < kTabulatedDimensions; ++d) h.of[d] = mix64(uint64_t(d) + 1);
    return h;
}
constexpr DimensionHashes kDimensionHashes = dimensionHashes();

uint64_t SobolSampler::dimensionKey(uint32_t dimension) const {
    const uint64_t hash = dimension < kTabulatedDimensions ? kDimensionHashes.of[dimension] : mix64(uint64_t(dimension) + 1);
    return mix64(key_ ^ hash);
}

// Every dimension shuffles the sample index its own way. Without that, the scrambled points'
// coarsest bit would be the index's lowest bit flipped by a constant in every dimension: two
// dimensions would fall in the same (or opposite) halves for all samples.
// Written with owenScramble(), the value of get1D() is
//   owenScramble(reverseBits(owenScramble(index, k1)), k2),
// and get2D()'s are owenScramble(reverseBits(i), k2) and owenScramble(sobolSecondDimension(i), k3)
// of i = owenScramble(index, k1); below the same with the reversals that cancel left out.
float SobolSampler::get1D(uint32_t dimension) const {
    const uint64_t key = dimensionKey(dimension);
    const uint32_t index = reverseBits(permuteReversed(reversedIndex_, uint32_t(key)));
    return toUnit(reverseBits(permuteReversed(index, uint32_t(key >> 32))));
}

glm::vec2 SobolSampler::get2D(uint32_t dimension) const {
    const uint64_t key = dimensionKey(dimension);
    const uint32_t index = reverseBits(permuteReversed(reversedIndex_, uint32_t(key >> 32)));  // not get1D's shuffle
    const uint64_t valueKey = mix64(key);
    return {toUnit(reverseBits(permuteReversed(index, uint32_t(valueKey)))),
            toUnit(reverseBits(permuteReversed(sobolSecondDimensionReversed(index), uint32_t(valueKey >> 32))))};
}

}  // namespace woven
