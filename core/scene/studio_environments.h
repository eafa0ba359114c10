#pragma once
// The environments woven generates for look development, as product-visualisation tools ship a
// few standard lights: a studio of three soft boxes (what lights a scene that brings no light), one
// large soft box, a window in a dim room and an overcast sky. Each is an equirectangular image made
// from a formula here, so nothing is downloaded; `--environment NAME` and the previewer's Lights
// section choose them.
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

// A soft-edged rectangular light on the sphere of directions: radiance inside half-angles
// (radians) either side of its centre's direction, falling to 0 over `soft` radians at its edges.
struct SoftBox {
    glm::vec3 centre;
    float halfWidth, halfHeight, soft, radiance;

    float at(const glm::vec3& d) const;  // radiance towards d (normalised)
};

struct StudioEnvironment {
    const char* name;
    const char* description;
    Environment (*make)();
};

const std::vector<StudioEnvironment>& studioEnvironments();
const StudioEnvironment* findStudioEnvironment(const std::string& name);  // null when there is none
std::string studioEnvironmentNames();  // "studio, softbox, window or overcast", for messages

}  // namespace woven
