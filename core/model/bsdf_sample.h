#pragma once
// A direction sampled from a BSDF, in the frame it was sampled in.
#include <glm/glm.hpp>

namespace woven {

struct BsdfSample {
    glm::vec3 wi;      // sampled direction
    glm::vec3 f;       // BSDF value (without the cosine)
    float pdf;         // solid-angle density of wi
    glm::vec3 weight;  // f * |cos(wi)| / pdf
};

}  // namespace woven
