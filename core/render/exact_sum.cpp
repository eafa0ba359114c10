#include "exact_sum.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
constexpr int kFractionBits = 60;
constexpr float kLargestSample = 4294967296.0f;  // 2^32
}  // namespace

void ExactSum::add(float sample) {
    if (!std::isfinite(sample)) return;
    // Exact in double: a float scaled by a power of two. Rounding to an integer is the one
    // rounding a sample ever sees, and it depends on the sample alone.
    const double scaled = std::ldexp(double(std::clamp(sample, -kLargestSample, kLargestSample)), kFractionBits);
    fixed_ += static_cast<Fixed>(std::nearbyint(scaled));
}

float ExactSum::mean(float count) const {
    if (count <= 0.0f) return 0.0f;
    return float(std::ldexp(double(fixed_), -kFractionBits) / double(count));
}

double ExactSum::value() const { return std::ldexp(double(fixed_), -kFractionBits); }

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
