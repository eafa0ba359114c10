#pragma once
// Inline float exp, log, log1p and sin/cos for the shading hot path, where libm's calls were about
// 13% of a render's time. Each is a polynomial on a reduced range, accurate to a few units in the
// last place of a float (relative error below 3e-7 over the ranges the model uses; checked against
// libm in tests/model/test_fast_math.cpp), so the model's measured accuracy is unchanged.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace woven {

namespace fast_math_detail {
inline float asFloat(uint32_t u) { float f; std::memcpy(&f, &u, 4); return f; }
inline uint32_t asBits(float f) { uint32_t u; std::memcpy(&u, &f, 4); return u; }
}  // namespace fast_math_detail

// e^x for x in [-87, 88.7], with no branch: a loop over an array of such x vectorises.
inline float fastExpInRange(float x) {
    using namespace fast_math_detail;
    // x = n ln2 + r, |r| <= ln2 / 2, ln2 split in two (Cody-Waite) so r keeps its digits.
    const float n = float(int(x * 1.44269504f + std::copysign(0.5f, x)));
    const float r = (x - n * 0.693145752f) - n * 1.42860677e-6f;
    // e^r by its Taylor series to r^7: |r|^8 / 8! < 2e-8 for |r| <= 0.347.
    const float p = 1.0f + r * (1.0f + r * (0.5f + r * (1.0f / 6 + r * (1.0f / 24 + r * (1.0f / 120 + r * (1.0f / 720 + r * (1.0f / 5040)))))));
    const int k = int(n), half = k / 2;
    // 2^k as 2^half 2^(k - half): 2^128 is no float, and a split with no branch vectorises. The
    // first product is exact, so the result is rounded once, as p 2^k would be.
    return p * asFloat(uint32_t(half + 127) << 23) * asFloat(uint32_t(k - half + 127) << 23);
}

// e^x; 0 below -87 (where the float result would be denormal), +inf above 88.7.
inline float fastExp(float x) {
    using namespace fast_math_detail;
    if (!(x > -87.0f)) return x != x ? x : 0.0f;
    if (x > 88.7f) return asFloat(0x7f800000u);
    return fastExpInRange(x);
}

// ln(x) for finite x > 0 (normal floats); -inf at 0, NaN below.
inline float fastLog(float x) {
    using namespace fast_math_detail;
    if (!(x > 0.0f)) return x == 0.0f ? -asFloat(0x7f800000u) : asFloat(0x7fc00000u);
    if (x == asFloat(0x7f800000u)) return x;
    uint32_t bits = asBits(x);
    int e = -127;
    if (bits < 0x00800000u) {  // denormal: scale into the normal range
        bits = asBits(x * 8388608.0f);  // 2^23
        e -= 23;
    }
    // x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(t), t = (m - 1) / (m + 1), |t| < 0.172.
    e += int(bits >> 23);
    uint32_t mantissa = (bits & 0x007fffffu) | 0x3f800000u;
    if (mantissa > 0x3fb504f3u) {  // m > sqrt(2): halve it
        mantissa -= 0x00800000u;
        ++e;
    }
    const float m = asFloat(mantissa);
    const float t = (m - 1.0f) / (m + 1.0f), t2 = t * t;
    const float atanh = t * (1.0f + t2 * (1.0f / 3 + t2 * (1.0f / 5 + t2 * (1.0f / 7 + t2 * (1.0f / 9)))));
    return float(e) * 0.693147181f + 2.0f * atanh;
}

// ln(1 + x) for x > -1, accurate where 1 + x rounds to 1 (Goldberg's correction: the rounding of
// u = 1 + x is divided back out).
inline float fastLog1p(float x) {
    const float u = 1.0f + x;
    if (u == 1.0f) return x;
    return fastLog(u) * (x / (u - 1.0f));
}

// sin and cos of an angle in [-pi/4, pi/2 + pi/4] (the model's quadrant angles), Taylor series on
// angle - pi/4 (|d| <= pi/2 would need more terms: the range is folded once about pi/4).
inline void fastSinCos(float angle, float* s, float* c) {
    // Fold about pi/4: for a in [pi/4, 3pi/4] use b = pi/2 - a in [-pi/4, pi/4] and swap.
    const bool fold = angle > 0.785398163f;
    const float a = fold ? 1.57079633f - angle : angle;
    const float a2 = a * a;
    // |a| <= pi/4: the series to a^11 and a^12 leave < 3e-8.
    const float sinA = a * (1.0f - a2 * (1.0f / 6 - a2 * (1.0f / 120 - a2 * (1.0f / 5040 - a2 * (1.0f / 362880 - a2 * (1.0f / 39916800))))));
    const float cosA = 1.0f - a2 * (0.5f - a2 * (1.0f / 24 - a2 * (1.0f / 720 - a2 * (1.0f / 40320 - a2 * (1.0f / 3628800 - a2 * (1.0f / 479001600))))));
    *s = fold ? cosA : sinA;
    *c = fold ? sinA : cosA;
}

}  // namespace woven
