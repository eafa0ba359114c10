#include "environment_mapping.h"

#include <cmath>

#include "math_constants.h"

namespace woven {

glm::vec3 equirectDirection(const glm::vec2& uv) {
    const float theta = kPi * uv.y, phi = 2.0f * kPi * uv.x;
    const float sinTheta = std::sin(theta);
    return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

glm::vec2 equirectUv(const glm::vec3& d) {
    float phi = std::atan2(d.x, -d.z);
    if (phi < 0.0f) phi += 2.0f * kPi;
    // atan2 rather than acos(d.y): accurate near the poles too, where sampling and pdfLi must agree.
    const float theta = std::atan2(std::sqrt(d.x * d.x + d.z * d.z), d.y);
    return {phi / (2.0f * kPi), theta / kPi};
}

glm::vec3 rotateY(const glm::vec3& d, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

}  // namespace woven
