#include "spherical_triangle.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"

namespace woven {

namespace {

float safeAsin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }
float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

// v less its component along the unit vector w.
glm::vec3 gramSchmidt(const glm::vec3& v, const glm::vec3& w) { return v - glm::dot(v, w) * w; }

}  // namespace

float angleBetween(const glm::vec3& v1, const glm::vec3& v2) {
    if (glm::dot(v1, v2) < 0.0f) return kPi - 2.0f * safeAsin(glm::length(v1 + v2) / 2.0f);
    return 2.0f * safeAsin(glm::length(v2 - v1) / 2.0f);
}

float triangleSolidAngle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& p) {
    const glm::vec3 da = glm::normalize(a - p), db = glm::normalize(b - p), dc = glm::normalize(c - p);
    return std::abs(2.0f * std::atan2(glm::dot(da, glm::cross(db, dc)),
                                      1.0f + glm::dot(da, db) + glm::dot(da, dc) + glm::dot(db, dc)));
}

std::optional<glm::vec2> sampleSphericalTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                                 const glm::vec3& p, float solidAngle, const glm::vec2& u) {
    const glm::vec3 da = glm::normalize(a - p), db = glm::normalize(b - p), dc = glm::normalize(c - p);
    glm::vec3 nab = glm::cross(da, db), nbc = glm::cross(db, dc), nca = glm::cross(dc, da);
    if (!(glm::dot(nab, nab) > 0.0f) || !(glm::dot(nbc, nbc) > 0.0f) || !(glm::dot(nca, nca) > 0.0f))
        return std::nullopt;
    nab = glm::normalize(nab);
    nbc = glm::normalize(nbc);
    nca = glm::normalize(nca);
    // The spherical triangle's angle at a; the sub-triangle (a, b, c') of area u.x * solidAngle
    // fixes c' on the arc from a to c (Arvo's inversion), then the direction is chosen on the
    // arc from b to c' so that the density is uniform.
    const float alpha = angleBetween(nab, -nca);
    const float areaPlusPi = u.x * solidAngle + kPi;
    const float cosAlpha = std::cos(alpha), sinAlpha = std::sin(alpha);
    const float sinArea = std::sin(areaPlusPi), cosArea = std::cos(areaPlusPi);
    const float sinPhi = sinArea * cosAlpha - cosArea * sinAlpha;
    const float cosPhi = cosArea * cosAlpha + sinArea * sinAlpha;
    const float k1 = cosPhi + cosAlpha;
    const float k2 = sinPhi - sinAlpha * glm::dot(da, db);
    const float cosBp = std::clamp((k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha),
                                   -1.0f, 1.0f);
    if (!std::isfinite(cosBp)) return std::nullopt;
    const glm::vec3 toC = gramSchmidt(dc, da);
    if (!(glm::dot(toC, toC) > 0.0f)) return std::nullopt;
    const glm::vec3 cp = cosBp * da + safeSqrt(1.0f - cosBp * cosBp) * glm::normalize(toC);
    const float cosTheta = 1.0f - u.y * (1.0f - glm::dot(cp, db));
    const glm::vec3 toCp = gramSchmidt(cp, db);
    const glm::vec3 w = glm::dot(toCp, toCp) > 0.0f
                            ? cosTheta * db + safeSqrt(1.0f - cosTheta * cosTheta) * glm::normalize(toCp)
                            : db;
    // Where w meets the plane of the triangle (Moller and Trumbore).
    const glm::vec3 e1 = b - a, e2 = c - a, s1 = glm::cross(w, e2);
    const float divisor = glm::dot(s1, e1);
    if (!(std::abs(divisor) > 0.0f)) return std::nullopt;
    const glm::vec3 s = p - a;
    float b1 = std::clamp(glm::dot(s, s1) / divisor, 0.0f, 1.0f);
    float b2 = std::clamp(glm::dot(w, glm::cross(s, e1)) / divisor, 0.0f, 1.0f);
    if (b1 + b2 > 1.0f) {
        const float sum = b1 + b2;
        b1 /= sum;
        b2 /= sum;
    }
    return glm::vec2(b1, b2);
}

}  // namespace woven
