#include "spherical_rectangle.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"
#include "spherical_triangle.h"

namespace woven {

namespace {

}  // namespace

SphericalRectangle::SphericalRectangle(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey,
                                       const glm::vec3& p)
    : p_(p) {
    const float width = glm::length(ex), height = glm::length(ey);
    if (!(width > 0.0f) || !(height > 0.0f)) return;
    x_ = ex / width;
    y_ = ey / height;
    z_ = glm::cross(x_, y_);
    const glm::vec3 d = corner - p;
    z0_ = glm::dot(d, z_);
    if (z0_ > 0.0f) {
        z_ = -z_;
        z0_ = -z0_;
    }
    if (!(z0_ < 0.0f)) return;  // p in the rectangle's plane sees no solid angle
    x0_ = glm::dot(d, x_);
    y0_ = glm::dot(d, y_);
    x1_ = x0_ + width;
    y1_ = y0_ + height;
    // The normals of the planes through p and each edge, and the spherical rectangle's inner
    // angles; its area is their sum less 2 pi.
    const glm::vec3 n0 = glm::normalize(glm::vec3(0.0f, z0_, -y0_));
    const glm::vec3 n1 = glm::normalize(glm::vec3(-z0_, 0.0f, x1_));
    const glm::vec3 n2 = glm::normalize(glm::vec3(0.0f, -z0_, y1_));
    const glm::vec3 n3 = glm::normalize(glm::vec3(z0_, 0.0f, -x0_));
    const float g0 = angleBetween(n0, -n1), g1 = angleBetween(n1, -n2);
    const float g2 = angleBetween(n2, -n3), g3 = angleBetween(n3, -n0);
    b0_ = n0.z;
    b1_ = n2.z;
    k_ = 2.0f * kPi - g2 - g3;
    solidAngle_ = std::max(0.0f, g0 + g1 - k_);
}

glm::vec3 SphericalRectangle::sample(const glm::vec2& u) const {
    // The sub-rectangle [x0, xu] of solid angle u.x times the whole fixes xu; then y is chosen
    // on that line by the cosine-weighted height h, which is uniform in solid angle there.
    const float au = u.x * solidAngle_ + k_;
    const float fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
    const float cu = std::clamp(std::copysign(1.0f, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0f, 1.0f);
    const float sinU = std::sqrt(std::max(0.0f, 1.0f - cu * cu));
    const float xu = sinU > 0.0f ? std::clamp(-cu * z0_ / sinU, x0_, x1_) : (-cu * z0_ > 0.0f ? x1_ : x0_);
    const float dist = std::sqrt(xu * xu + z0_ * z0_);
    const float h0 = y0_ / std::sqrt(dist * dist + y0_ * y0_), h1 = y1_ / std::sqrt(dist * dist + y1_ * y1_);
    const float hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    const float yv = hv2 < 1.0f - 1e-6f ? std::clamp(hv * dist / std::sqrt(1.0f - hv2), y0_, y1_) : (hv > 0.0f ? y1_ : y0_);
    return p_ + xu * x_ + yv * y_ + z0_ * z_;
}

}  // namespace woven
