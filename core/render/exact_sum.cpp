#include "exact_sum.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace woven {

namespace {
constexpr int kFractionBits = 60;  // value() scales by 2^-60
constexpr float kLargestSample = 4294967296.0f;  // 2^32
}  // namespace

void ExactSum::add(float sample) {
    if (!std::isfinite(sample)) return;
    // The sample is mantissa x 2^exponent exactly, so in units of 2^-60 it is mantissa shifted:
    // rounding to a whole unit (half to even, as nearbyint would round the scaled double) is the
    // one rounding a sample ever sees, and it depends on the sample alone. In integers, as a
    // film adds 16 sums per pixel and pass: ldexp and a double's conversion to 128 bits cost
    // ten times as much.
    const float clamped = std::clamp(sample, -kLargestSample, kLargestSample);
    uint32_t bits;
    std::memcpy(&bits, &clamped, sizeof bits);
    const int biased = int((bits >> 23) & 0xffu);
    const uint32_t mantissa = biased == 0 ? (bits & 0x7fffffu) : ((bits & 0x7fffffu) | 0x800000u);
    const int shift = (biased == 0 ? -149 : biased - 150) + kFractionBits;
    Fixed units = 0;
    if (shift >= 0) {
        units = Fixed(mantissa) << shift;  // at most 2^24 x 2^69
    } else if (shift > -25) {  // else below half a unit: 0
        const int k = -shift;
        uint32_t whole = mantissa >> k;
        const uint32_t rest = mantissa & ((1u << k) - 1u), half = 1u << (k - 1);
        if (rest > half || (rest == half && (whole & 1u))) ++whole;
        units = whole;
    }
    fixed_ += (bits >> 31) ? -units : units;
}

float ExactSum::mean(float count) const {
    if (count <= 0.0f) return 0.0f;
    return float(value() / double(count));
}

double ExactSum::value() const { return double(fixed_) * 0x1p-60; }  // 2^-kFractionBits

std::array<float, ExactSum::kFloatWords> ExactSum::floatWords() const {
    __extension__ typedef unsigned __int128 Bits;
    Bits bits = static_cast<Bits>(fixed_);
    std::array<float, kFloatWords> out{};
    for (float& w : out) {
        w = float(uint32_t(bits & 0xffffff));
        bits >>= 24;
    }
    return out;
}

std::optional<ExactSum> ExactSum::fromFloatWords(const std::array<float, kFloatWords>& words) {
    __extension__ typedef unsigned __int128 Bits;
    Bits bits = 0;
    for (int i = kFloatWords - 1; i >= 0; --i) {
        const float w = words[size_t(i)];
        const float limit = i == kFloatWords - 1 ? 256.0f : 16777216.0f;  // 128 - 5 x 24 = 8 bits on top
        if (!(w >= 0.0f && w < limit && w == std::floor(w))) return std::nullopt;
        bits = (bits << 24) | Bits(uint32_t(w));
    }
    ExactSum sum;
    sum.fixed_ = static_cast<Fixed>(bits);
    return sum;
}

std::array<uint32_t, 4> ExactSum::words() const {
    __extension__ typedef unsigned __int128 Bits;
    const Bits bits = static_cast<Bits>(fixed_);
    return {uint32_t(bits), uint32_t(bits >> 32), uint32_t(bits >> 64), uint32_t(bits >> 96)};
}

ExactSum ExactSum::fromWords(const std::array<uint32_t, 4>& words) {
    __extension__ typedef unsigned __int128 Bits;
    Bits bits = 0;
    for (int i = 3; i >= 0; --i) bits = (bits << 32) | words[size_t(i)];
    ExactSum sum;
    sum.fixed_ = static_cast<Fixed>(bits);
    return sum;
}

}  // namespace woven
