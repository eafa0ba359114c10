#pragma once
// How finely a uv held in a float or a double can place a point on the cloth. A mesh's uv is a
// float: at |uv| = 1e7 its neighbouring values lie a whole unit apart, tens of threads at
// ordinary thread counts, and every point of a triangle lands on a few edges of the threads.
// Where the spacing of those values exceeds a quarter of a weave element (where farFieldWeight()
// starts) the point is only known to within several threads, and ShadingInput::uvSpacing lets
// the filter shade it by the weave's far field, as a footprint of that size.
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace woven {

// The spacing in uv units, per axis, of the values T takes near `uv`: |uv| epsilon, within a
// factor of 2 above the exact one and continuous in uv, so the far field fades in smoothly (the
// preview's woven.frag computes the same).
template <class T>
glm::dvec2 uvSpacing(const glm::dvec2& uv) {
    return glm::abs(uv) * double(std::numeric_limits<T>::epsilon());
}

// The |u|, |v| from which uvSpacing<T>() exceeds a quarter of a weave element at `repeat`
// elements per uv unit: below them the spacing changes nothing.
template <class T>
glm::dvec2 resolvedUvLimit(const glm::vec2& repeat) {
    return 0.25 / (glm::dvec2(repeat) * double(std::numeric_limits<T>::epsilon()));
}

// Whether `uv` lies within resolvedUvLimit()'s `limit`: the cheap test before uvSpacing().
inline bool resolvesThreads(const glm::dvec2& uv, const glm::dvec2& limit) {
    return std::abs(uv.x) <= limit.x && std::abs(uv.y) <= limit.y;
}

}  // namespace woven
