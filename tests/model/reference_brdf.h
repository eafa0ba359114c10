#pragma once
// An independent double-precision Ashikhmin-Shirley BRDF written straight from MODEL.md
// section 4, the yardstick the float implementation in core/model is checked against.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace woven::test {

constexpr double kPi = 3.14159265358979323846;

struct ReferenceAS {
    double ex, ey, rs;
    glm::dvec3 rd;

    double exponent(const glm::dvec3& h) const {
        const double s = h.x * h.x + h.y * h.y;
        if (s <= 0.0) return ex;  // phi undefined at h = n: both agree only if the lobe is symmetric
        return (ex * h.x * h.x + ey * h.y * h.y) / s;
    }
    // p_h(h), the source's eq. 1.
    double halfVectorPdf(const glm::dvec3& h) const {
        if (h.z <= 0.0) return 0.0;
        return std::sqrt((ex + 1.0) * (ey + 1.0)) / (2.0 * kPi) * std::pow(h.z, exponent(h));
    }
    // f(k1, k2) without the cosine; k1, k2 unit vectors in the lobe frame (z = normal, x = e_x axis).
    // They are normalised here: float inputs are unit only to about 1e-7, which near h.k -> 0
    // would otherwise move h.k itself by a percent.
    glm::dvec3 eval(glm::dvec3 k1, glm::dvec3 k2) const {
        k1 = glm::normalize(k1);
        k2 = glm::normalize(k2);
        if (k1.z <= 0.0 || k2.z <= 0.0) return glm::dvec3(0.0);
        const glm::dvec3 h = glm::normalize(k1 + k2);
        const double hk = glm::dot(h, k1);
        const double fresnel = rs + (1.0 - rs) * std::pow(1.0 - hk, 5.0);
        const double spec = std::sqrt((ex + 1.0) * (ey + 1.0)) / (8.0 * kPi) * std::pow(h.z, exponent(h)) /
                            (hk * std::max(k1.z, k2.z)) * fresnel;
        const double diffuse = 28.0 / (23.0 * kPi) * (1.0 - rs) * (1.0 - std::pow(1.0 - k1.z / 2.0, 5.0)) *
                               (1.0 - std::pow(1.0 - k2.z / 2.0, 5.0));
        return diffuse * rd + glm::dvec3(spec);
    }
};

inline glm::dvec3 toDouble(const glm::vec3& v) { return glm::dvec3(v); }

// Unit direction from spherical angles (theta from +z, phi from +x).
inline glm::vec3 sphericalDirection(double theta, double phi) {
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                     float(std::cos(theta)));
}

}  // namespace woven::test
