#include "mesh_attributes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <vector>

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

namespace {
// A triangle's corner positions from the least (compared x, then y, then z), keeping their
// cyclic order, so that every rotation of one triangle gives the same key.
using CornerKey = std::array<float, 9>;

CornerKey cornerKey(const Mesh& mesh, const glm::uvec3& t) {
    // + 0: -0 becomes +0, so that the bits hashed agree where the values compare equal.
    const std::array<glm::vec3, 3> p = {mesh.positions[t.x] + 0.0f, mesh.positions[t.y] + 0.0f, mesh.positions[t.z] + 0.0f};
    const auto less = [](const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    const int first = less(p[1], p[0]) ? (less(p[2], p[1]) ? 2 : 1) : (less(p[2], p[0]) ? 2 : 0);
    CornerKey key;
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) key[size_t(3 * k + c)] = p[size_t((first + k) % 3)][c];
    return key;
}

uint64_t hashKey(const CornerKey& key) {
    uint64_t h = 0;
    for (float f : key) {
        uint32_t bits;
        std::memcpy(&bits, &f, 4);
        h = (h ^ bits) * 0x9E3779B97F4A7C15ull;  // Fibonacci hashing: every bit moves the high ones
    }
    return h ^ (h >> 29);
}
}  // namespace

size_t removeDuplicateTriangles(Mesh& mesh) {
    // Open addressing over a power of two at least twice the triangles, each slot a kept
    // triangle's index and its hash's top bits. Each look-up misses the cache: the hashes come
    // first, so that the slot of a triangle some way ahead is fetched while this one is looked
    // up (a node-based set took 1.1 s for two million triangles, this 0.09 s). A buffer of
    // at most 4 GiB holds fewer than 2^32 - 1 triangles.
    constexpr uint32_t kEmpty = ~0u;
    constexpr size_t kAhead = 16;
    struct Slot {
        uint32_t tag, kept;
    };
    const size_t n = mesh.triangles.size();
    std::vector<uint64_t> hashes(n);
    for (size_t i = 0; i < n; ++i) hashes[i] = hashKey(cornerKey(mesh, mesh.triangles[i]));
    size_t mask = 1;
    while (mask < 2 * n) mask *= 2;
    std::vector<Slot> slots(mask--, Slot{0, kEmpty});
    size_t kept = 0;
    for (size_t i = 0; i < n; ++i) {
        if (i + kAhead < n) __builtin_prefetch(&slots[size_t(hashes[i + kAhead]) & mask]);
        const glm::uvec3 t = mesh.triangles[i];
        const uint32_t tag = uint32_t(hashes[i] >> 32);
        size_t s = size_t(hashes[i]) & mask;
        bool duplicate = false;
        for (; slots[s].kept != kEmpty && !duplicate; s = (s + 1) & mask)
            duplicate = slots[s].tag == tag && cornerKey(mesh, mesh.triangles[slots[s].kept]) == cornerKey(mesh, t);
        if (duplicate) continue;
        slots[s] = {tag, uint32_t(kept)};
        mesh.triangles[kept++] = t;
    }
    const size_t removed = n - kept;
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

namespace {
// Appends a copy of vertex v with every per-vertex attribute; returns its index.
uint32_t duplicateVertex(Mesh& mesh, uint32_t v) {
    mesh.positions.push_back(mesh.positions[v]);
    if (!mesh.normals.empty()) mesh.normals.push_back(mesh.normals[v]);
    if (!mesh.uvs.empty()) mesh.uvs.push_back(mesh.uvs[v]);
    if (!mesh.uvs1.empty()) mesh.uvs1.push_back(mesh.uvs1[v]);
    if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
    if (!mesh.tangents.empty()) mesh.tangents.push_back(mesh.tangents[v]);
    return uint32_t(mesh.positions.size() - 1);
}

// The sign of a triangle's UV orientation against its winding: negative where the UVs are mirrored.
float uvOrientation(const Mesh& mesh, const std::vector<glm::vec2>& uv, const glm::uvec3& t) {
    const glm::vec2 d1 = uv[t.y] - uv[t.x], d2 = uv[t.z] - uv[t.x];
    return d1.x * d2.y - d1.y * d2.x < 0.0f ? -1.0f : 1.0f;
}
}  // namespace

void computeTangents(Mesh& mesh, int uvSet) {
    // Split vertices used with both UV orientations: the mirrored side gets its own copy.
    {
        const std::vector<glm::vec2>& uv = uvSet == 1 ? mesh.uvs1 : mesh.uvs;
        std::vector<signed char> orientation(mesh.positions.size(), 0);
        std::vector<uint32_t> mirrorCopy(mesh.positions.size(), UINT32_MAX);
        std::vector<float> triangleSign(mesh.triangles.size());
        for (size_t i = 0; i < mesh.triangles.size(); ++i) triangleSign[i] = uvOrientation(mesh, uv, mesh.triangles[i]);
        for (size_t i = 0; i < mesh.triangles.size(); ++i) {
            glm::uvec3& t = mesh.triangles[i];
            const signed char sign = triangleSign[i] < 0.0f ? -1 : 1;
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = t[k];
                if (orientation[v] == 0) orientation[v] = sign;
                if (orientation[v] == sign) continue;
                if (mirrorCopy[v] == UINT32_MAX) mirrorCopy[v] = duplicateVertex(mesh, v);
                t[k] = mirrorCopy[v];
            }
        }
    }
    const std::vector<glm::vec2>& uv = uvSet == 1 ? mesh.uvs1 : mesh.uvs;
    const size_t n = mesh.positions.size();
    std::vector<glm::vec3> dpdu(n, glm::vec3(0.0f)), dpdv(n, glm::vec3(0.0f));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 e1 = mesh.positions[t.y] - mesh.positions[t.x];
        const glm::vec3 e2 = mesh.positions[t.z] - mesh.positions[t.x];
        const glm::vec2 d1 = uv[t.y] - uv[t.x];
        const glm::vec2 d2 = uv[t.z] - uv[t.x];
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
