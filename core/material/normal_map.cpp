#include "normal_map.h"

#include <cmath>

namespace woven {

namespace {
glm::vec3 projectOut(const glm::vec3& v, const glm::vec3& n) { return v - glm::dot(v, n) * n; }
bool usableLength(float length) { return length > 1e-12f && std::isfinite(length); }
}  // namespace

std::optional<Frame> tangentSpace(const SurfaceHit& hit) {
    Frame f;
    f.z = hit.nsFlipped ? -hit.ns : hit.ns;
    const glm::vec3 t = projectOut(hit.dpdu, f.z), b = projectOut(hit.dpdv, f.z);
    const float tl = glm::length(t), bl = glm::length(b);
    if (!usableLength(tl) || !usableLength(bl)) return std::nullopt;
    f.x = t / tl;
    f.y = b / bl;
    return f;
}

glm::vec3 normalMapped(const TextureSampler& map, const SurfaceHit& hit) {
    const std::optional<Frame> tbn = tangentSpace(hit);
    if (!tbn) return hit.ns;
    glm::vec3 m = glm::vec3(map.eval(hit.tex)) * 2.0f - 1.0f;
    m.x *= map.scale();
    m.y *= map.scale();
    const glm::vec3 perturbed = tbn->toWorld(m);
    const float length = glm::length(perturbed);
    if (!usableLength(length)) return hit.ns;
    return (hit.nsFlipped ? -perturbed : perturbed) / length;
}

}  // namespace woven
