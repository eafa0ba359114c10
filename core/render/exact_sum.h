#pragma once
// A sum of float samples whose value cannot depend on the order they were added in, so a frame
// rendered in one go and the merge of renders of its sample ranges hold the same sums, and so
// the same means, bit for bit. Each sample is rounded once to a multiple of 2^-60 (about 1e-18)
// and added to a 128-bit integer: integer addition is exact and associative. Samples beyond
// +-2^32 (about 4e9, far beyond any radiance the renderer means) are clamped there, which
// leaves room for 2^35 samples of that size before the integer could overflow.
#include <array>
#include <cstdint>
#include <optional>

namespace woven {

class ExactSum {
public:
    // Non-finite samples add nothing (the renderer drops them before they get here).
    void add(float sample);
    ExactSum& operator+=(const ExactSum& other) {
        fixed_ += other.fixed_;
        return *this;
    }
    bool operator==(const ExactSum& other) const { return fixed_ == other.fixed_; }
    bool operator!=(const ExactSum& other) const { return fixed_ != other.fixed_; }

    // The mean of `count` samples rounded to float; 0 when count is 0.
    float mean(float count) const;
    // The sum itself, rounded to double.
    double value() const;

    // How files of earlier versions kept it: the 128-bit two's complement integer as four 32-bit
    // words, least significant first.
    std::array<uint32_t, 4> words() const;
    static ExactSum fromWords(const std::array<uint32_t, 4>& words);
    // How a frame file keeps it in float channels, which every EXR reader takes: the same
    // integer as six whole numbers below 2^24, which a float holds exactly, least significant
    // first (the last holds the top 8 bits). fromFloatWords() gives nothing unless every word
    // is a whole number in its range.
    static constexpr int kFloatWords = 6;
    std::array<float, kFloatWords> floatWords() const;
    static std::optional<ExactSum> fromFloatWords(const std::array<float, kFloatWords>& words);

private:
    __extension__ typedef __int128 Fixed;  // GCC and Clang, on every 64-bit target
    Fixed fixed_ = 0;                      // the sum in units of 2^-60
};

}  // namespace woven
