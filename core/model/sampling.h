#pragma once
// Warping functions from the unit square, and the counter-based random numbers that make a
// frame a pure function of (scene, seed, pixel, sample index).
#include <glm/glm.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "math_constants.h"

namespace woven {

inline glm::vec3 sampleCosineHemisphere(const glm::vec2& u) {
    // Concentric disk mapping (Shirley-Chiu), lifted to the hemisphere.
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    float r, phi;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};
    if (a * a > b * b) { r = a; phi = 0.78539816f * (b / a); }
    else { r = b; phi = 1.5707963f - 0.78539816f * (a / b); }
    const float x = r * std::cos(phi), y = r * std::sin(phi);
    return {x, y, std::sqrt(std::fmax(0.0f, 1.0f - x * x - y * y))};
}

inline glm::vec3 sampleUniformSphere(const glm::vec2& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
    const float phi = 6.2831853f * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Uniform point on the unit disk (polar: the radius sqrt(u.x)).
inline glm::vec2 sampleUniformDisk(const glm::vec2& u) {
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Cone around +z up to cosMax, uniform in solid angle.
inline glm::vec3 sampleUniformCone(const glm::vec2& u, float cosMax) {
    const float cosTheta = 1.0f - u.x * (1.0f - cosMax);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Uniform point on a triangle (barycentrics b1, b2), Heitz 2019 low-distortion map.
inline glm::vec2 sampleTriangleBarycentrics(const glm::vec2& u) {
    float b0, b1;
    if (u.y > u.x) { b0 = u.x / 2; b1 = u.y - b0; }
    else { b1 = u.y / 2; b0 = u.x - b1; }
    return {b1, 1.0f - b0 - b1};
}

constexpr uint64_t mix64(uint64_t z) {  // SplitMix64 finaliser
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// Random numbers keyed by (seed, pixel, sample index): never by thread or tile, so disjoint
// sample ranges rendered anywhere merge into exactly the render of their union.
class Rng {
public:
    Rng(uint64_t seed, uint64_t pixel, uint64_t sampleIndex)
        : state_(mix64(seed ^ mix64(pixel * 0x9e3779b97f4a7c15ULL ^ mix64(sampleIndex + 0x632be59bd9b4e019ULL)))) {}
    explicit Rng(uint64_t seed) : state_(mix64(seed)) {}

    uint32_t nextU32() {  // PCG-XSH-RR step on a 64-bit LCG
        uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + 1442695040888963407ULL;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    float uniform() { return float(nextU32() >> 8) * 0x1p-24f; }  // [0, 1)
    glm::vec2 uniform2() { float a = uniform(); return {a, uniform()}; }

private:
    uint64_t state_;
};

}  // namespace woven
