#pragma once
// The luminance of a linear Rec. 709 RGB colour: how bright a colour looks, in one number, for
// weighing lights, estimating noise and comparing images.
#include <glm/vec3.hpp>

namespace woven {

// In float or double.
template <typename T, glm::qualifier Q>
T luminance(const glm::vec<3, T, Q>& c) {
    return T(0.2126) * c.r + T(0.7152) * c.g + T(0.0722) * c.b;
}

}  // namespace woven
