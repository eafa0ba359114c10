#pragma once
// Where an Environment's equirectangular image lies on the sphere of directions, for the
// renderer's environment light and the previewer alike. +y up; u = 0 looks towards -z and u
// grows towards +x (u = 0.25 is +x, 0.5 is +z, 0.75 is -x); v = 0 is the top row (+y), v = 1
// the bottom (-y). So theta = pi v from +y and phi = 2 pi u from -z towards +x:
//     dir = (sin theta sin phi, cos theta, -sin theta cos phi)
// Environment::rotation turns the image about +y by the right-hand rule (a positive angle takes
// the image's -z towards -x, as seen from above).
#include <glm/glm.hpp>

namespace woven {

// The unrotated mapping and its inverse (d need not be normalised).
glm::vec3 equirectDirection(const glm::vec2& uv);
glm::vec2 equirectUv(const glm::vec3& d);

// d turned by `angle` radians about +y.
glm::vec3 rotateY(const glm::vec3& d, float angle);

}  // namespace woven
