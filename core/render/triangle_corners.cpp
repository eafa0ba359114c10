#include "triangle_corners.h"

#include <utility>

#include "frame.h"

namespace woven {

Corners cornerPositions(const Mesh& mesh, int instance, unsigned prim, float b1, float b2) {
    Corners c;
    c.tri = mesh.triangles[prim];
    c.b1 = b1;
    c.b2 = b2;
    c.placement = instance >= 0 ? &(*mesh.instances)[size_t(instance)] : nullptr;
    c.mirrored = c.placement && glm::determinant(glm::mat3(*c.placement)) < 0.0f;
    if (c.mirrored) {
        std::swap(c.tri.y, c.tri.z);
        std::swap(c.b1, c.b2);
    }
    const glm::mat4* m = c.placement;
    for (int k = 0; k < 3; ++k)
        c.p[k] = m ? glm::vec3(*m * glm::vec4(mesh.positions[c.tri[k]], 1.0f)) : mesh.positions[c.tri[k]];
    return c;
}

Corners hitCorners(const Mesh& mesh, int instance, unsigned prim, float b1, float b2) {
    Corners c = cornerPositions(mesh, instance, prim, b1, b2);
    const glm::mat4* m = c.placement;
    const glm::mat3 normalMatrix = m ? glm::transpose(glm::inverse(glm::mat3(*m))) : glm::mat3(1.0f);
    for (int k = 0; k < 3; ++k) {
        const unsigned v = c.tri[k];
        if (!mesh.normals.empty()) c.n[k] = m ? glm::normalize(normalMatrix * mesh.normals[v]) : mesh.normals[v];
        if (!mesh.tangents.empty()) {
            const glm::vec4& t = mesh.tangents[v];
            c.t[k] = m ? glm::vec4(Frame::fromNormalAndAxis(c.n[k], glm::mat3(*m) * glm::vec3(t)).x,
                                   c.mirrored ? -t.w : t.w)
                       : t;
        }
    }
    return c;
}

}  // namespace woven
