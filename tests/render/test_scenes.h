#pragma once
// Small hand-made scenes for the render tests: every vertex, normal and uv is known, so
// expected values come from geometry, not from the code under test.
#include <memory>
#include <string>

#include "scene_description.h"

namespace woven::test {

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

// An axis-aligned box [lo, hi] of six quads whose fronts face inwards.
inline std::vector<Mesh> boxInside(const glm::vec3& lo, const glm::vec3& hi, int material = -1) {
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    return {quad("floor", p[0], p[1], p[5], p[4], material),  quad("ceiling", p[3], p[7], p[6], p[2], material),
            quad("back", p[0], p[3], p[2], p[1], material),   quad("front", p[4], p[5], p[6], p[7], material),
            quad("left", p[0], p[4], p[7], p[3], material),   quad("right", p[1], p[2], p[6], p[5], material)};
}

inline std::shared_ptr<SceneDescription> sceneWith(std::vector<Mesh> meshes, std::vector<Material> materials = {}) {
    auto scene = std::make_shared<SceneDescription>();
    scene->source = "test.gltf";
    scene->meshes = std::move(meshes);
    scene->materials = std::move(materials);
    return scene;
}

}  // namespace woven::test
