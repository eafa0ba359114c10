#pragma once
// How bright a light may be. Samples are summed exactly up to 2^32 (about 4e9) and clamped
// beyond (exact_sum.h), so a light far brighter than any real one would render wrong, not
// brighter; an infinite one makes NaN and a blank frame. In woven's radiometric units the sun
// gives about 1000 W/m^2 and a 100 W bulb about 10 W/sr: a billion leaves room for any
// physical scene.
#include <glm/glm.hpp>
#include <string>

namespace woven {

constexpr float kMaxLightValue = 1e9f;

// Empty when every channel of `value` (a light's intensity, an environment's radiance or
// colour) is finite and in [0, kMaxLightValue]; otherwise what is wrong, for a message.
std::string lightValueProblem(const glm::vec3& value);

}  // namespace woven
