#pragma once
// Sampling a triangle by the solid angle it subtends from a point (Arvo 1995, "Stratified
// sampling of spherical triangles", in pbrt-v4's formulation), for next-event estimation of
// triangle lights: area sampling's density in solid angle is d^2 / (cos_light area), unbounded
// where a lamp is close or seen edge on (a ceiling just above a lamp), where this one is
// constant over the triangle's directions.
#include <optional>

#include <glm/glm.hpp>

namespace woven {

// The angle between unit vectors, accurate near 0 and pi where acos(dot) is not (pbrt-v4's
// AngleBetween): the spherical polygons' angles near a lamp's plane are there.
float angleBetween(const glm::vec3& v1, const glm::vec3& v2);

// The solid angle of triangle (a, b, c) seen from p (Van Oosterom and Strackee 1983).
float triangleSolidAngle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& p);

// Solid angles within which sampling by solid angle is numerically sound: below, the triangle's
// directions are too close for float (and area sampling is as good); above, it covers nearly
// the whole hemisphere, where Arvo's inversion loses its precision. pbrt-v4's bounds.
inline constexpr float kMinSphericalSampleArea = 3e-4f, kMaxSphericalSampleArea = 6.22f;

// A point of triangle (a, b, c), as barycentrics (b1, b2) of b and c, whose direction from p
// is uniform over the triangle's solid angle `solidAngle` (triangleSolidAngle(), within the
// bounds above). nullopt for a triangle seen edge on.
std::optional<glm::vec2> sampleSphericalTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                                 const glm::vec3& p, float solidAngle, const glm::vec2& u);

}  // namespace woven
