#include "mesh_attributes.h"

#include <cmath>

#include "frame.h"

namespace woven {

size_t removeDegenerateTriangles(Mesh& mesh) {
    size_t kept = 0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 cross = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                           mesh.positions[t.z] - mesh.positions[t.x]);
        const float area2 = glm::dot(cross, cross);
        const bool degenerate = t.x == t.y || t.y == t.z || t.x == t.z || !(area2 > 0.0f) || !std::isfinite(area2);
        if (!degenerate) mesh.triangles[kept++] = t;
    }
    const size_t removed = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    return removed;
}

void computeVertexNormals(Mesh& mesh) {
    std::vector<glm::vec3> sum(mesh.positions.size(), glm::vec3(0.0f));
    for (const glm::uvec3& t : mesh.triangles) {
        // The unnormalised cross product has length 2 x area: the area weighting comes free.
        const glm::vec3 n = glm::cross(mesh.positions[t.y] - mesh.positions[t.x],
                                       mesh.positions[t.z] - mesh.positions[t.x]);
        for (int k = 0; k < 3; ++k) sum[t[k]] += n;
    }
    mesh.normals.resize(sum.size());
    for (size_t v = 0; v < sum.size(); ++v) {
        const float length = glm::length(sum[v]);
        mesh.normals[v] = length > 0.0f ? sum[v] / length : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

void computeTangents(Mesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<glm::vec3> dpdu(n, glm::vec3(0.0f)), dpdv(n, glm::vec3(0.0f));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 e1 = mesh.positions[t.y] - mesh.positions[t.x];
        const glm::vec3 e2 = mesh.positions[t.z] - mesh.positions[t.x];
        const glm::vec2 d1 = mesh.uvs[t.y] - mesh.uvs[t.x];
        const glm::vec2 d2 = mesh.uvs[t.z] - mesh.uvs[t.x];
        const float det = d1.x * d2.y - d1.y * d2.x;
        if (!(std::abs(det) > 0.0f)) continue;
        // Solve [e1 e2] = [dp/du dp/dv] [d1 d2]; weighting each triangle by its area in
        // position space (|e1 x e2|) relative to UV space keeps small slivers from dominating.
        const float weight = glm::length(glm::cross(e1, e2)) / std::abs(det);
        const glm::vec3 tu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 tv = (e2 * d1.x - e1 * d2.x) / det;
        if (!std::isfinite(tu.x + tu.y + tu.z + tv.x + tv.y + tv.z)) continue;
        for (int k = 0; k < 3; ++k) {
            dpdu[t[k]] += tu * weight;
            dpdv[t[k]] += tv * weight;
        }
    }
    mesh.tangents.resize(n);
    for (size_t v = 0; v < n; ++v) {
        const glm::vec3& normal = mesh.normals[v];
        const glm::vec3 t = Frame::fromNormalAndAxis(normal, dpdu[v]).x;
        const float w = glm::dot(glm::cross(normal, t), dpdv[v]) < 0.0f ? -1.0f : 1.0f;
        mesh.tangents[v] = glm::vec4(t, w);
    }
}

}  // namespace woven
