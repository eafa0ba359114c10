// The samplers: values in [0, 1), the Sobol sampler's stratification of a pixel's first 2^k
// samples, dimensions and pixels independent of one another, and the independent sampler as
// the Rng it replaces.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "sample_dimensions.h"
#include "sampler.h"

namespace woven {
namespace {

constexpr uint64_t kSeed = 11;

TEST(Sampler, ValuesLieInTheUnitInterval) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent})
        for (uint64_t pixel : {0ull, 7ull, 123456ull})
            for (uint64_t index : {0ull, 1ull, 255ull, (1ull << 32) - 1, 1ull << 32, (1ull << 62) - 1})
                for (uint32_t dim = 0; dim < 64; ++dim) {
                    Sampler sampler(kind, kSeed, pixel, index);
                    const float a = sampler.get1D(dim);
                    const glm::vec2 b = sampler.get2D(dim);
                    for (float v : {a, b.x, b.y}) {
                        ASSERT_GE(v, 0.0f) << samplerName(kind) << " pixel " << pixel << " index " << index;
                        ASSERT_LT(v, 1.0f) << samplerName(kind) << " pixel " << pixel << " index " << index;
                    }
                }
}

// The first 2^k samples of a pixel put one point in each of the 2^k elementary intervals of
// every shape (2^a x 2^b cells, a + b = k) for each 2D dimension, and one in each 1/2^k of [0, 1)
// for each 1D one: what makes the error fall faster than independent samples'.
TEST(SobolSampler, FirstPowerOfTwoSamplesOfAPixelAreStratified) {
    for (uint64_t pixel : {0ull, 4242ull})
        for (uint32_t dim : {kPixelDimension, sampleDimension(Subpath::Camera, 1, SampleUse::BsdfDirection),
                             sampleDimension(Subpath::Light, 3, SampleUse::LightDirection)})
            for (int k = 0; k <= 10; ++k) {
                const uint32_t n = 1u << k;
                std::vector<glm::vec2> points;
                std::set<uint32_t> cells1D;
                for (uint32_t i = 0; i < n; ++i) {
                    const SobolSampler s(kSeed, pixel, i);
                    points.push_back(s.get2D(dim));
                    cells1D.insert(uint32_t(s.get1D(dim) * float(n)));
                }
                EXPECT_EQ(cells1D.size(), n) << "1D, dimension " << dim << ", 2^" << k << " samples";
                for (int a = 0; a <= k; ++a) {
                    std::set<std::pair<uint32_t, uint32_t>> cells;
                    for (const glm::vec2& p : points)
                        cells.insert({uint32_t(p.x * float(1u << a)), uint32_t(p.y * float(1u << (k - a)))});
                    EXPECT_EQ(cells.size(), n) << "dimension " << dim << ", 2^" << k << " samples in 2^" << a
                                               << " x 2^" << (k - a) << " cells";
                }
            }
}

// Dimensions and pixels draw unrelated numbers: no two share a sequence, and two dimensions of
// one pixel fall in the same half of [0, 1) for about half the samples. Unshuffled sample
// indices would make every pair agree for all samples or for none. 1024 samples: the fraction
// has a standard deviation of 1/64, so 0.4 to 0.6 is over six of them.
TEST(SobolSampler, DimensionsAndPixelsAreIndependent) {
    constexpr uint32_t kSamples = 1024;
    std::vector<uint32_t> dims;
    for (int vertex = 0; vertex < 3; ++vertex)
        for (SampleUse use : {SampleUse::LightChoice, SampleUse::LightPoint, SampleUse::BsdfDirection,
                              SampleUse::BsdfLobe, SampleUse::Roulette})
            dims.push_back(sampleDimension(Subpath::Camera, vertex, use));
    // Each sequence: dimension's x, first 1D then 2D, per (pixel, dimension).
    std::set<std::vector<float>> sequences;
    for (uint64_t pixel : {0ull, 1ull, 640ull}) {
        std::vector<std::vector<float>> values;  // per dimension and kind, over samples
        for (uint32_t dim : dims) {
            std::vector<float> one, two;
            for (uint32_t i = 0; i < kSamples; ++i) {
                const SobolSampler s(kSeed, pixel, i);
                one.push_back(s.get1D(dim));
                two.push_back(s.get2D(dim).x);
            }
            values.push_back(one);
            values.push_back(two);
        }
        for (size_t a = 0; a < values.size(); ++a)
            for (size_t b = a + 1; b < values.size(); ++b) {
                int same = 0;
                for (uint32_t i = 0; i < kSamples; ++i) same += (values[a][i] < 0.5f) == (values[b][i] < 0.5f);
                EXPECT_NEAR(double(same) / kSamples, 0.5, 0.1) << "pixel " << pixel << ", sequences " << a << " and " << b;
            }
        for (const auto& v : values) EXPECT_TRUE(sequences.insert(v).second) << "a sequence repeats, pixel " << pixel;
    }
}

// Sample indices are 64-bit: the block of 2^32 samples from 2^32 on is scrambled anew.
TEST(SobolSampler, SamplesPast32BitsAreNotTheFirstAgain) {
    for (uint32_t dim : {0u, 5u})
        EXPECT_NE(SobolSampler(kSeed, 3, 5).get2D(dim), SobolSampler(kSeed, 3, 5 + (1ull << 32)).get2D(dim));
    EXPECT_NE(SobolSampler(kSeed, 3, 5).get2D(0), SobolSampler(kSeed + 1, 3, 5).get2D(0)) << "the seed changes nothing";
}

// --sampler independent renders as woven did before the Sobol sampler: Rng's numbers in order.
TEST(IndependentSampler, DrawsRngsNumbersInOrderWhateverTheDimension) {
    Rng rng(kSeed, 77, 9);
    Sampler sampler(SamplerKind::Independent, kSeed, 77, 9);
    EXPECT_EQ(sampler.get2D(kPixelDimension), rng.uniform2());
    EXPECT_EQ(sampler.get1D(40), rng.uniform());
    EXPECT_EQ(sampler.get2D(3), rng.uniform2());
}

TEST(Sampler, NamesRoundTripAndUnknownOnesAreRefused) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent})
        EXPECT_EQ(samplerKind(samplerName(kind)), kind);
    EXPECT_THROW(samplerKind("halton"), std::invalid_argument);
}

}  // namespace
}  // namespace woven
