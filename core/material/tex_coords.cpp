#include "tex_coords.h"

#include <cmath>

namespace woven {

namespace {
template <class V>
V interpolate(const std::vector<V>& values, const glm::uvec3& t, float b0, float b1, float b2) {
    const V v = b0 * values[t.x] + b1 * values[t.y] + b2 * values[t.z];
    for (int c = 0; c < V::length(); ++c)
        if (!std::isfinite(v[c])) return V(0.0f);
    return v;
}
}  // namespace

TexCoords interpolateTexCoords(const Mesh& mesh, unsigned triangle, float b1, float b2) {
    const glm::uvec3 t = mesh.triangles[triangle];
    const float b0 = 1.0f - b1 - b2;
    TexCoords tc;
    if (!mesh.uvs.empty()) {
        tc.uv[0] = interpolate(mesh.uvs, t, b0, b1, b2);
        tc.hasUv = true;
    }
    if (!mesh.uvs1.empty()) tc.uv[1] = interpolate(mesh.uvs1, t, b0, b1, b2);
    if (!mesh.colors.empty()) tc.color = interpolate(mesh.colors, t, b0, b1, b2);
    return tc;
}

}  // namespace woven
