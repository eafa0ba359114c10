// The preview draws an instanced mesh (Mesh::instances) by instanced draws: the frame shows every
// copy where, and facing the way, the same mesh expanded into the world shows it, mirrored copies
// of a single-sided material included, and their shadows.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "flat_cloth.h"
#include "gl_test_context.h"

namespace woven::test {
namespace {

// Nine small squares over the cloth, facing up (+y), on a 3 x 3 grid: plain, turned, scaled
// unevenly, mirrored in x (which keeps the front) and mirrored in y (which turns it down, so
// a single-sided copy shows its back to the camera above and is not drawn).
std::vector<glm::mat4> placements() {
    std::vector<glm::mat4> m;
    for (int i = 0; i < 9; ++i) {
        const glm::vec3 at(-0.6f + 0.6f * float(i % 3), 0.2f, -0.6f + 0.6f * float(i / 3));
        glm::mat4 own(1.0f);
        if (i == 1) own = glm::rotate(glm::mat4(1.0f), 0.6f, glm::vec3(0, 1, 0));
        if (i == 2) own = glm::scale(glm::mat4(1.0f), glm::vec3(0.6f, 1.0f, 1.3f));
        if (i == 3) own = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
        if (i == 5) own = glm::scale(glm::mat4(1.0f), glm::vec3(1, -1, 1));
        m.push_back(glm::translate(glm::mat4(1.0f), at) * own);
    }
    return m;
}

Mesh square() {
    Mesh m;
    m.name = "square";
    m.positions = {{-0.2f, 0, 0.2f}, {0.2f, 0, 0.2f}, {0.2f, 0, -0.2f}, {-0.2f, 0, -0.2f}};  // counter-clockwise from +y
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.tangents.assign(4, glm::vec4(1, 0, 0, 1));
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// The copies as separate world-space meshes, as the loader expanded them before instancing.
std::vector<Mesh> expandedCopies(const Mesh& mesh, const std::vector<glm::mat4>& placements) {
    std::vector<Mesh> out;
    for (const glm::mat4& m : placements) {
        Mesh copy = mesh;
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
        const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
        for (size_t v = 0; v < copy.positions.size(); ++v) {
            copy.positions[v] = glm::vec3(m * glm::vec4(mesh.positions[v], 1.0f));
            copy.normals[v] = glm::normalize(normalMatrix * mesh.normals[v]);
            copy.tangents[v] = glm::vec4(glm::normalize(glm::mat3(m) * glm::vec3(mesh.tangents[v])), mirrored ? -1.0f : 1.0f);
        }
        if (mirrored)
            for (glm::uvec3& t : copy.triangles) std::swap(t.y, t.z);
        out.push_back(std::move(copy));
    }
    return out;
}

TEST(InstancedDraw, ShowsEveryCopyAsItsExpansionDoes) {
    ensureHeadlessGl();
    WovenParams p;
    p.repeat = glm::vec2(8.0f);
    SceneDescription base = flatClothScene(p);
    Material red;
    red.name = "red";
    red.baseColor = glm::vec4(0.9f, 0.1f, 0.05f, 1.0f);
    red.doubleSided = false;
    base.materials.push_back(red);
    Mesh mesh = square();
    mesh.material = int(base.materials.size()) - 1;

    SceneDescription instanced = base, expanded = base;
    const std::vector<glm::mat4> m = placements();
    Mesh copies = mesh;
    copies.instances = std::make_shared<const std::vector<glm::mat4>>(m);
    instanced.meshes.push_back(copies);
    for (Mesh& c : expandedCopies(mesh, m)) expanded.meshes.push_back(std::move(c));

    constexpr int kSize = 96;
    const Image a = previewRadiance(instanced, kSize, kSize), b = previewRadiance(expanded, kSize, kSize),
                none = previewRadiance(base, kSize, kSize);
    // The same vertices, placed on the GPU instead of the CPU: float rounding may move an edge
    // across a pixel centre, so a few pixels along the squares' edges may differ, no more.
    size_t differ = 0, covered = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const float d = glm::length(a.pixels[i] - b.pixels[i]), scale = std::max(glm::length(b.pixels[i]), 1e-3f);
        differ += d > 1e-4f * scale;
        covered += glm::length(b.pixels[i] - none.pixels[i]) > 1e-3f;
    }
    EXPECT_LT(double(differ), 0.01 * double(a.pixels.size())) << differ << " pixels differ";
    // The squares (and their shadows) are in the picture at all: 8 of the 9 are seen from above.
    EXPECT_GT(double(covered), 0.05 * double(a.pixels.size()));
}

}  // namespace
}  // namespace woven::test
