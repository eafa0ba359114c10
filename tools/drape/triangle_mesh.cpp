#include "triangle_mesh.h"

#include <cmath>

namespace drape {

namespace {

void smoothNormals(TriangleMesh& mesh) {
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        // Unnormalised: weights each face by its area.
        const glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        mesh.normals[a] += n;
        mesh.normals[b] += n;
        mesh.normals[c] += n;
    }
    for (glm::vec3& n : mesh.normals) n = glm::normalize(n);
}

}  // namespace

TriangleMesh clothMesh(const ClothSimulation& cloth) {
    TriangleMesh mesh;
    const int n = cloth.resolution();
    mesh.positions = cloth.positions();
    mesh.uvs.resize(mesh.positions.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) mesh.uvs[j * n + i] = glm::vec2(i, j) / float(n - 1);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            // The grid starts in the y = const plane with +i along x and +j along z, so the
            // counter-clockwise front (a, c, b) faces +y: up, towards the light, before draping.
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    smoothNormals(mesh);
    return mesh;
}

TriangleMesh sphereMesh(const glm::vec3& center, float radius, int segments, int rings) {
    TriangleMesh mesh;
    for (int r = 0; r <= rings; ++r) {
        const float theta = float(M_PI) * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2.0f * float(M_PI) * s / segments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            mesh.positions.push_back(center + radius * n);
            mesh.normals.push_back(n);
            mesh.uvs.push_back(glm::vec2(float(s) / segments, float(r) / rings));
        }
    }
    const uint32_t row = segments + 1;
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
            if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, c, b});  // the pole rows have one triangle
            if (r != rings - 1) mesh.indices.insert(mesh.indices.end(), {b, c, d});
        }
    return mesh;
}

TriangleMesh roundedBoxMesh(const glm::vec3& center, const glm::vec3& halfExtent, float radius, int divisions) {
    TriangleMesh mesh;
    const glm::vec3 inner = halfExtent - glm::vec3(radius);
    // Six faces of a subdivided cube; each face's two edge directions in the order that makes
    // the counter-clockwise front face outwards.
    const glm::vec3 axes[6][3] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                  {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                  {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    for (const auto& face : axes) {
        const uint32_t base = uint32_t(mesh.positions.size());
        for (int j = 0; j <= divisions; ++j)
            for (int i = 0; i <= divisions; ++i) {
                const float s = 2.0f * i / divisions - 1.0f, t = 2.0f * j / divisions - 1.0f;
                const glm::vec3 cube = (face[0] + s * face[1] + t * face[2]) * halfExtent;
                const glm::vec3 nearest = glm::clamp(cube, -inner, inner);
                const glm::vec3 normal = glm::normalize(cube - nearest);
                mesh.positions.push_back(center + nearest + radius * normal);
                mesh.normals.push_back(normal);
            }
        const uint32_t row = divisions + 1;
        for (int j = 0; j < divisions; ++j)
            for (int i = 0; i < divisions; ++i) {
                const uint32_t a = base + j * row + i, b = a + 1, c = a + row, d = c + 1;
                mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
            }
    }
    return mesh;
}

TriangleMesh quadMesh(const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV) {
    TriangleMesh mesh;
    mesh.positions = {corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV};
    mesh.normals.assign(4, glm::normalize(glm::cross(edgeU, edgeV)));
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

TriangleMesh facingSquare(const glm::vec3& center, const glm::vec3& normal, float size) {
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(helper, n));
    const glm::vec3 b = glm::cross(n, t);  // cross(t, b) = n: the front faces along n
    return quadMesh(center - 0.5f * size * (t + b), size * t, size * b);
}

}  // namespace drape
