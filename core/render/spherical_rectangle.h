#pragma once
// Sampling a rectangle by the solid angle it subtends from a point (Urena, Fajardo and King
// 2013, "An area-preserving parametrization for spherical rectangles"), for next-event
// estimation of rectangular lamps: one sample over the whole lamp, where its two triangles
// would each need their own spherical triangle and a choice between them.
#include <glm/glm.hpp>

namespace woven {

// The rectangle with corner `corner` and orthogonal edges `ex` and `ey`, as seen from `p`.
class SphericalRectangle {
public:
    SphericalRectangle(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey, const glm::vec3& p);

    // The solid angle it subtends; 0 from a point in its plane.
    float solidAngle() const { return solidAngle_; }
    // A point of the rectangle whose direction from p is uniform over solidAngle() (which must
    // be above 0); u in [0, 1)^2.
    glm::vec3 sample(const glm::vec2& u) const;

private:
    // The local frame: x and y along the edges, z the normal facing away from p, so that the
    // rectangle spans [x0, x1] x [y0, y1] at height z0 < 0 (the paper's notation).
    glm::vec3 p_, x_, y_, z_;
    float x0_ = 0.0f, x1_ = 0.0f, y0_ = 0.0f, y1_ = 0.0f, z0_ = 0.0f;
    float b0_ = 0.0f, b1_ = 0.0f, k_ = 0.0f, solidAngle_ = 0.0f;
};

}  // namespace woven
