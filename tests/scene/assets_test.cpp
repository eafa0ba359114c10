// The committed assets: the draped cloth and every scene file in assets/ load, and carry what
// they promise (triangle count, UV layout, woven parameters of the paper's variants, a light).
// Also gltf-transform's variants of the cloth: quantized and meshopt-compressed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

#include "scene_loader.h"
#include "uv_scale.h"

namespace woven {
namespace {

using ::testing::HasSubstr;

const std::string kAssets = WOVEN_ASSETS_DIR;
const std::string kData = WOVEN_TEST_DATA_DIR;

const Mesh& meshNamed(const SceneDescription& scene, const std::string& prefix) {
    for (const Mesh& m : scene.meshes)
        if (m.name.rfind(prefix, 0) == 0) return m;
    throw std::runtime_error("no mesh " + prefix);
}

int materialNamed(const SceneDescription& scene, const std::string& name) {
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].name == name) return int(m);
    return -1;
}

bool hasEmitter(const SceneDescription& scene) {
    for (const Mesh& m : scene.meshes)
        if (m.material >= 0 && scene.materials[m.material].emission != glm::vec3(0.0f)) return true;
    return false;
}

TEST(Assets, DrapedClothIsAWovenGridOfAbout15000Triangles) {
    const SceneDescription scene = loadScene(kAssets + "/cloth_drape.glb");
    const Mesh& cloth = meshNamed(scene, "Cloth/");
    EXPECT_EQ(cloth.positions.size(), 88u * 88u);
    EXPECT_EQ(cloth.triangles.size(), 2u * 87u * 87u);  // none degenerate: the springs kept the grid apart
    ASSERT_EQ(cloth.uvs.size(), cloth.positions.size());
    EXPECT_EQ(cloth.uvs.front(), glm::vec2(0, 0));
    EXPECT_EQ(cloth.uvs.back(), glm::vec2(1, 1));
    EXPECT_EQ(cloth.tangents.size(), cloth.positions.size());
    ASSERT_GE(cloth.material, 0);
    EXPECT_EQ(scene.materials[cloth.material].name, "Cloth");
    ASSERT_TRUE(scene.materials[cloth.material].woven.has_value());
    // The cloth rests on the sphere (top at y = 1) and above the ground.
    float top = -1e9f, bottom = 1e9f;
    for (const glm::vec3& p : cloth.positions) top = std::max(top, p.y), bottom = std::min(bottom, p.y);
    EXPECT_NEAR(top, 1.0f, 0.03f);
    EXPECT_GT(bottom, 0.0f);
    EXPECT_TRUE(scene.hasCamera);
    EXPECT_TRUE(hasEmitter(scene));
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(Assets, EverySceneFileLoads) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kAssets)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        const SceneDescription scene = loadScene(entry.path().string());
        // Each shows a woven cloth (most name it "Cloth"; the lampshade's is its "Shade").
        EXPECT_TRUE(std::any_of(scene.materials.begin(), scene.materials.end(),
                                [](const auto& m) { return m.woven.has_value(); }));
        EXPECT_TRUE(hasEmitter(scene) || !scene.lights.empty() || scene.environment.color != glm::vec3(0.0f));
        ++count;
    }
    EXPECT_GE(count, 7);
}

TEST(Assets, PaperVariants) {
    const auto cloth = [](const std::string& file) {
        const SceneDescription scene = loadScene(kAssets + "/" + file);
        return *scene.materials[materialNamed(scene, "Cloth")].woven;
    };
    const WovenParams a = cloth("paper_a_anisotropy.json");
    EXPECT_EQ(a.ex, 100.0f);
    EXPECT_EQ(a.ey, 2.0f);
    EXPECT_EQ(cloth("paper_b_curvature.json").cy, 0.75f);
    EXPECT_EQ(cloth("paper_c_twill.json").pattern, glm::ivec3(1, 2, 1));
    EXPECT_EQ(cloth("paper_d_satin.json").pattern, glm::ivec3(9, 1, 3));
    EXPECT_EQ(loadScene(kAssets + "/default_scene.json").render.width, 640);
}

// The default scene shows cloth as it is: denim's 25 ends and 16 picks per cm on the draped mesh
// (its draft's spacing through "scale": "draft"), not threads centimetres wide.
TEST(Assets, DefaultSceneIsDenimAtItsRealThreadCount) {
    const SceneDescription scene = loadScene(kAssets + "/default_scene.json");
    const int cloth = materialNamed(scene, "Cloth");
    ASSERT_GE(cloth, 0);
    std::vector<size_t> meshes;
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        if (scene.meshes[m].material == cloth) meshes.push_back(m);
    const glm::dvec2 metresPerUv = worldLengthPerUv(scene, meshes);
    const glm::vec2 repeat = scene.materials[size_t(cloth)].woven->repeat;
    EXPECT_NEAR(repeat.x / (metresPerUv.x * 100.0), 25.0, 0.25);
    EXPECT_NEAR(repeat.y / (metresPerUv.y * 100.0), 16.0, 0.16);
    EXPECT_TRUE(scene.hasCamera);
}

TEST(Assets, IndirectSceneHidesItsLampFromTheCloth) {
    const SceneDescription scene = loadScene(kAssets + "/converge_indirect.json");
    EXPECT_EQ(scene.environment.color, glm::vec3(0.0f));
    EXPECT_TRUE(scene.lights.empty());
    const Mesh& lamp = meshNamed(scene, "Lamp/");
    const Mesh& cloth = meshNamed(scene, "Cloth/");
    // The lamp's front faces the back wall (-z); every cloth vertex is in front of it (+z side),
    // so no cloth point sees the emitting side.
    const glm::vec3 lampNormal = lamp.normals[0];
    EXPECT_LT(lampNormal.z, -0.99f);
    for (const glm::vec3& p : cloth.positions) ASSERT_LT(glm::dot(p - lamp.positions[0], lampNormal), 0.0f);
}

TEST(Assets, GltfTransformQuantizedClothMatchesTheOriginal) {
    const Mesh original = meshNamed(loadScene(kAssets + "/cloth_drape.glb"), "Cloth/");
    const SceneDescription quantized = loadScene(kData + "/cloth_quantized.glb");
    const Mesh& q = meshNamed(quantized, "Cloth/");
    ASSERT_EQ(q.positions.size(), original.positions.size());
    ASSERT_EQ(q.triangles.size(), original.triangles.size());
    // quantize stores positions as 16-bit normalized integers over the mesh's bounds (about
    // 1.7 m, so steps of 2.6e-5 m) and UVs in 12 bits by default: 1e-3 m and 1e-3 in UV are generous.
    for (size_t v = 0; v < q.positions.size(); ++v) {
        ASSERT_NEAR(glm::length(q.positions[v] - original.positions[v]), 0.0f, 1e-3f) << v;
        ASSERT_NEAR(glm::length(q.uvs[v] - original.uvs[v]), 0.0f, 1e-3f) << v;
        ASSERT_GT(glm::dot(q.normals[v], original.normals[v]), 0.99f) << v;
    }
    // (gltf-transform drops extensions it does not know, WOVEN_fabric included: a scene file
    // restores the woven material; see docs/SCENE_FORMAT.md.)
}

TEST(Assets, GltfTransformMeshoptClothMatchesTheOriginal) {
    const Mesh original = meshNamed(loadScene(kAssets + "/cloth_drape.glb"), "Cloth/");
    const Mesh q = meshNamed(loadScene(kData + "/cloth_meshopt.glb"), "Cloth/");
    ASSERT_EQ(q.positions.size(), original.positions.size());
    EXPECT_EQ(q.triangles.size(), original.triangles.size());
    // meshopt quantizes as quantize does (above) and reorders the vertices for the codec, then
    // compresses losslessly: each vertex has its original within the same 1e-3 in position and
    // UV, and normals within 8 degrees (8-bit octahedral normals, dot 0.99).
    for (size_t v = 0; v < q.positions.size(); ++v) {
        size_t best = 0;
        float bestDistance = std::numeric_limits<float>::infinity();
        for (size_t o = 0; o < original.positions.size(); ++o) {
            const float d = glm::length(q.positions[v] - original.positions[o]) + glm::length(q.uvs[v] - original.uvs[o]);
            if (d < bestDistance) bestDistance = d, best = o;
        }
        ASSERT_LT(bestDistance, 2e-3f) << v;
        ASSERT_GT(glm::dot(q.normals[v], original.normals[best]), 0.99f) << v;
    }
}

}  // namespace
}  // namespace woven
