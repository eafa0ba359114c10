#pragma once
// How far from the origin a position may lie: a vertex (after its node's transform, skin and
// morph targets), a camera, a point or spot light, a scene file's camera target. Embree 3 aborts
// the process on a ray whose origin or direction exceeds 1.844e18 (its FLT_LARGE) on any axis
// (RayK::valid()), and float overflows sooner: an environment's power, 4 pi^2 r^2 L over the
// scene's bounding sphere, passes 3.4e38 from about 5e13 m at the brightest light woven accepts
// (light_limits.h). 1e12 m, seven times the Earth's distance from the sun, stays a factor 50
// below that and 10^5 below Embree's bound, which leaves room for unnormalised shadow-ray
// directions (up to twice the limit) and for the camera woven places to frame a scene without
// one (up to 6.4 times the limit away). Geospatial glTF files, the largest real ones, place
// nodes at the Earth's radius, 6.4e6 m.
#include <glm/glm.hpp>
#include <string>

namespace woven {

constexpr float kMaxCoordinate = 1e12f;

// Empty when every coordinate of `p` is finite and within kMaxCoordinate of 0; otherwise what is
// wrong, for a message that names the position first ("camera.position: ...").
std::string coordinateProblem(const glm::vec3& p);

}  // namespace woven
