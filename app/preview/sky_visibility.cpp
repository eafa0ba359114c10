#include "sky_visibility.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string_view>

#include "frame.h"
#include "math_constants.h"
#include "render_scene.h"
#include "yarn_noise.h"

namespace woven {

namespace {

constexpr float kGoldenRatioFraction = 0.618034f;  // of a turn between successive spiral points

// The share of kSkyRays directions about n from p that no geometry blocks.
float visibleShare(const RenderScene& scene, const glm::vec3& p, const glm::vec3& n, uint32_t key) {
    SurfaceHit hit;
    hit.p = p;
    hit.ng = hit.ns = n;
    return openShare(scene, hit, n, kSkyRays, vertexTurn(key));
}

template <class T>
size_t hashBytes(const std::vector<T>& values, size_t seed) {
    const std::string_view bytes(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    return seed * 1099511628211ULL ^ std::hash<std::string_view>{}(bytes);
}

}  // namespace

glm::vec3 spiralDirection(int i, int count, float turn) {
    const float r = std::sqrt((float(i) + 0.5f) / float(count));
    const float phi = 2.0f * kPi * (float(i) * kGoldenRatioFraction + turn);
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - r * r))};
}

float vertexTurn(uint32_t key) { return float(hash32(key) >> 8) * 0x1p-24f; }

float openShare(const RenderScene& scene, const SurfaceHit& from, const glm::vec3& n, int count, float turn) {
    const Frame frame = Frame::fromNormal(n);
    int open = 0;
    for (int i = 0; i < count; ++i) open += !scene.occludedToInfinity(from, frame.toWorld(spiralDirection(i, count, turn)));
    return float(open) / float(count);
}

size_t skyVisibilityKey(const SceneDescription& scene) {
    size_t key = scene.meshes.size();
    for (const Mesh& mesh : scene.meshes) {
        key = hashBytes(mesh.positions, key);
        key = hashBytes(mesh.normals, key);
        key = hashBytes(mesh.triangles, key);
        key = hashBytes(mesh.instances ? *mesh.instances : std::vector<glm::mat4>{}, key);
    }
    return key;
}

std::vector<std::vector<glm::vec2>> skyVisibility(const SceneDescription& scene) {
    std::vector<std::vector<glm::vec2>> all;
    // A scene of the environment alone (the previewer shows one; core has nothing to trace).
    if (std::none_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangles.empty(); })) {
        for (const Mesh& mesh : scene.meshes) all.emplace_back(mesh.positions.size(), glm::vec2(1.0f));
        return all;
    }
    const RenderScene traced(std::make_shared<const SceneDescription>(scene));
    for (const Mesh& mesh : scene.meshes) {
        std::vector<glm::vec2> shares(mesh.positions.size(), glm::vec2(1.0f));
        if (!mesh.instances && mesh.normals.size() == mesh.positions.size())
            for (size_t i = 0; i < shares.size(); ++i) {
                const glm::vec3 n = mesh.normals[i];
                if (!(glm::dot(n, n) > 0.0f)) continue;
                const glm::vec3 unit = glm::normalize(n);
                const uint32_t key = uint32_t(i) * 2U + uint32_t(all.size()) * 0x9E3779B9U;
                shares[i] = {visibleShare(traced, mesh.positions[i], unit, key),
                             visibleShare(traced, mesh.positions[i], -unit, key + 1U)};
            }
        all.push_back(std::move(shares));
    }
    return all;
}

}  // namespace woven
