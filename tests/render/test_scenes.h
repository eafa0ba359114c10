#pragma once
// Small hand-made scenes for the render tests: every vertex, normal and uv is known, so
// expected values come from geometry, not from the code under test.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <atomic>

#include "math_constants.h"
#include "render_job.h"
#include "render_scene.h"
#include "scene_description.h"

namespace woven::test {

// Whether anything blocks the segment from a point in space (no surface under it) to `target`:
// a shadow ray from a point that is no hit, through the scene's own occlusion query.
inline bool occludedFrom(const RenderScene& scene, const glm::vec3& p, const glm::vec3& target) {
    SurfaceHit from;
    from.p = p;
    from.ng = from.ns = glm::normalize(target - p);
    return scene.occluded(from, target);
}

// A planar quad a, b, c, d (counter-clockwise seen from its front) with uv (0,0), (1,0), (1,1),
// (0,1) at its corners, times `uvScale`.
inline Mesh quad(const std::string& name, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                 const glm::vec3& d, int material = -1, float uvScale = 1.0f) {
    Mesh m;
    m.name = name;
    m.positions = {a, b, c, d};
    m.uvs = {glm::vec2(0, 0), glm::vec2(uvScale, 0), glm::vec2(uvScale, uvScale), glm::vec2(0, uvScale)};
    m.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
    m.material = material;
    return m;
}

// An axis-aligned box [lo, hi] of six quads (twelve triangles) whose fronts face inwards.
inline std::vector<Mesh> boxInside(const glm::vec3& lo, const glm::vec3& hi, int material = -1) {
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
    const char* names[6] = {"z-", "z+", "y-", "y+", "x-", "x+"};
    const glm::vec3 centre = 0.5f * (lo + hi);
    std::vector<Mesh> walls;
    for (int f = 0; f < 6; ++f) {
        const glm::vec3 a = p[faces[f][0]], b = p[faces[f][1]], c = p[faces[f][2]], d = p[faces[f][3]];
        const bool inwards = glm::dot(glm::cross(b - a, c - a), centre - a) > 0.0f;
        walls.push_back(inwards ? quad(names[f], a, b, c, d, material) : quad(names[f], a, d, c, b, material));
    }
    return walls;
}

// A sphere about the origin, `rings` x `segments` quads of its latitude-longitude grid, with
// its normals and uv = (longitude, latitude) / their ranges.
inline Mesh uvSphere(float radius, int rings, int segments, int material) {
    Mesh m;
    m.name = "sphere";
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = kPi * r / rings, phi = 2.0f * kPi * s / segments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            m.positions.push_back(radius * n);
            m.normals.push_back(n);
            m.uvs.emplace_back(float(s) / segments, float(r) / rings);
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const unsigned a = unsigned(r * (segments + 1) + s), b = a + 1, c = a + unsigned(segments + 1), d = c + 1;
            m.triangles.emplace_back(a, b, c);  // outward: counter-clockwise seen from outside
            m.triangles.emplace_back(b, d, c);
        }
    m.material = material;
    return m;
}

// A camera `height` above the origin looking straight down, image up towards -z (so image x
// runs along +x and image y down the page along +z).
inline Camera lookingDown(float height, float yfov) {
    Camera c;
    c.cameraToWorld = glm::inverse(glm::lookAt(glm::vec3(0, height, 0), glm::vec3(0), glm::vec3(0, 0, -1)));
    c.yfov = yfov;
    return c;
}

inline std::shared_ptr<SceneDescription> sceneWith(std::vector<Mesh> meshes, std::vector<Material> materials = {}) {
    auto scene = std::make_shared<SceneDescription>();
    scene->source = "test.gltf";
    scene->meshes = std::move(meshes);
    scene->materials = std::move(materials);
    return scene;
}

// The film of a whole render of `scene` with `settings`.
inline FilmImage render(std::shared_ptr<const SceneDescription> scene, RenderSettings settings) {
    RenderJob job(std::move(scene), settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    return job.snapshot();
}

}  // namespace woven::test
