// ExactSum: the same samples give the same sum in any order and any grouping (what makes a
// merge of sample ranges equal one render of their union), and its words (integer and float)
// round-trip.
#include "exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace woven {
namespace {

// Radiance-like samples over 20 orders of magnitude, where float and double sums depend on order.
std::vector<float> wideSamples(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> exponent(-12.0f, 8.0f), sign(0.0f, 1.0f);
    std::vector<float> samples;
    for (int i = 0; i < n; ++i) samples.push_back(std::pow(10.0f, exponent(rng)) * (sign(rng) < 0.05f ? -1.0f : 1.0f));
    return samples;
}

ExactSum sumOf(const std::vector<float>& samples, size_t begin, size_t end) {
    ExactSum sum;
    for (size_t i = begin; i < end; ++i) sum.add(samples[i]);
    return sum;
}

TEST(ExactSum, OrderAndGroupingDoNotMatter) {
    std::vector<float> samples = wideSamples(5000, 1);
    const ExactSum inOrder = sumOf(samples, 0, samples.size());
    // The double sums in the two orders differ: what the old film and merge saw.
    double forward = 0.0, backward = 0.0;
    for (float s : samples) forward += s;
    for (auto it = samples.rbegin(); it != samples.rend(); ++it) backward += *it;
    EXPECT_NE(forward, backward);

    ExactSum ranges = sumOf(samples, 2000, 5000);
    ranges += sumOf(samples, 0, 700);
    ranges += sumOf(samples, 700, 2000);
    EXPECT_EQ(ranges, inOrder);

    std::shuffle(samples.begin(), samples.end(), std::mt19937(2));
    EXPECT_EQ(sumOf(samples, 0, samples.size()), inOrder);
    EXPECT_EQ(sumOf(samples, 0, samples.size()).mean(5000.0f), inOrder.mean(5000.0f));
}

TEST(ExactSum, MeanIsTheSumOverTheCountToFloatPrecision) {
    const std::vector<float> samples = wideSamples(1000, 3);
    long double exact = 0.0L;
    for (float s : samples) exact += s;
    const float mean = sumOf(samples, 0, samples.size()).mean(1000.0f);
    EXPECT_NEAR(mean, float(exact / 1000.0L), std::abs(float(exact / 1000.0L)) * 1e-6f);

    ExactSum small;
    for (int i = 0; i < 3; ++i) small.add(0.1f);
    EXPECT_EQ(small.mean(3.0f), 0.1f);
    EXPECT_EQ(ExactSum().mean(0.0f), 0.0f);
    EXPECT_EQ(small.mean(0.0f), 0.0f);
}

TEST(ExactSum, NonFiniteSamplesAddNothingAndHugeOnesAreClamped) {
    ExactSum sum;
    sum.add(2.0f);
    sum.add(std::numeric_limits<float>::quiet_NaN());
    sum.add(std::numeric_limits<float>::infinity());
    EXPECT_EQ(sum.mean(1.0f), 2.0f);

    ExactSum huge;
    huge.add(1e30f);
    EXPECT_EQ(huge.mean(1.0f), 4294967296.0f);
    // 2^35 samples of the clamped size still fit: 2^16 of them certainly add up exactly.
    ExactSum many;
    for (int i = 0; i < 65536; ++i) many.add(-1e30f);
    EXPECT_EQ(many.mean(65536.0f), -4294967296.0f);
}

TEST(ExactSum, WordsRoundTripNegativeAndPositiveSums) {
    for (float value : {0.0f, 1.0f, -1.0f, 3.5e-12f, -123456.789f, 4e9f}) {
        ExactSum sum;
        sum.add(value);
        sum.add(value);
        const ExactSum back = ExactSum::fromWords(sum.words());
        EXPECT_EQ(back, sum) << value;
        EXPECT_EQ(back.mean(2.0f), sum.mean(2.0f)) << value;
    }
    ExactSum one;
    one.add(1.0f);  // 2^60 units: bit 28 of the second word
    EXPECT_EQ(one.words(), (std::array<uint32_t, 4>{0u, 1u << 28, 0u, 0u}));
    ExactSum minusOne;
    minusOne.add(-1.0f);  // two's complement
    EXPECT_EQ(minusOne.words(), (std::array<uint32_t, 4>{0u, 0xF0000000u, 0xFFFFFFFFu, 0xFFFFFFFFu}));
}

// Each sample is rounded once, to the nearest multiple of 2^-60 (half to even): what the double
// 2^60 x sample, exact, rounds to. Over every exponent a float has, subnormals and ties included.
TEST(ExactSum, EachSampleIsItsNearestWholeUnit) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> bits;
    std::vector<float> samples = {0.5f * std::ldexp(1.0f, -60), 1.5f * std::ldexp(1.0f, -60), 2.5f * std::ldexp(1.0f, -60),
                                  std::ldexp(1.0f, -61), std::numeric_limits<float>::denorm_min(), 4294967296.0f};
    for (int i = 0; i < 100000; ++i) {
        uint32_t b = bits(rng);
        float f;
        std::memcpy(&f, &b, sizeof f);
        if (std::isfinite(f) && std::abs(f) <= 4294967296.0f) samples.push_back(f);
    }
    for (const float f : samples) {
        ExactSum sum;
        sum.add(f);
        const double units = std::nearbyint(std::ldexp(double(f), 60));
        EXPECT_EQ(sum.value(), std::ldexp(units, -60)) << f;
        // value() rounds to double: the integer words say the same, exactly.
        ExactSum twice = sum;
        twice += sum;
        EXPECT_EQ(twice.value(), 2.0 * std::ldexp(units, -60)) << f;
    }
}

// The float words frame files keep: whole numbers below 2^24 (2^8 on top), which round-trip
// through float channels; anything else is no word of a sum.
TEST(ExactSum, FloatWordsRoundTripAndRefuseWhatNoSumGives) {
    for (float value : {0.0f, 1.0f, -1.0f, 3.5e-12f, -123456.789f, 4e9f}) {
        ExactSum sum;
        sum.add(value);
        sum.add(value * 0.3f);
        const std::optional<ExactSum> back = ExactSum::fromFloatWords(sum.floatWords());
        ASSERT_TRUE(back) << value;
        EXPECT_EQ(*back, sum) << value;
        EXPECT_EQ(back->value(), sum.value()) << value;
    }
    ExactSum one;
    one.add(1.0f);  // 2^60 units: bit 12 of the third word
    EXPECT_EQ(one.floatWords(), (std::array<float, 6>{0.0f, 0.0f, 4096.0f, 0.0f, 0.0f, 0.0f}));
    ExactSum minusOne;
    minusOne.add(-1.0f);
    EXPECT_EQ(minusOne.floatWords(), (std::array<float, 6>{0.0f, 0.0f, 16773120.0f, 16777215.0f, 16777215.0f, 255.0f}));
    EXPECT_DOUBLE_EQ(minusOne.value(), -1.0);
    for (const std::array<float, 6>& bad : {std::array<float, 6>{0.5f, 0, 0, 0, 0, 0}, std::array<float, 6>{0, 16777216.0f, 0, 0, 0, 0},
                                           std::array<float, 6>{0, 0, 0, 0, 0, 256.0f}, std::array<float, 6>{-1.0f, 0, 0, 0, 0, 0},
                                           std::array<float, 6>{0, 0, std::nanf(""), 0, 0, 0}})
        EXPECT_FALSE(ExactSum::fromFloatWords(bad));
}

}  // namespace
}  // namespace woven
