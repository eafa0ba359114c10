// glTF loading: each supported feature in a small file written by GltfBuilder, with the expected
// numbers worked out by hand in the comments; each broken file gives its own error, naming the file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "gltf_builder.h"
#include "mesh_instances.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "../common/load_error.h"

namespace woven {
namespace {

using test::loadError;

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

constexpr float kEps = 1e-5f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float eps = kEps) {
    EXPECT_NEAR(actual.x, expected.x, eps);
    EXPECT_NEAR(actual.y, expected.y, eps);
    EXPECT_NEAR(actual.z, expected.z, eps);
}

// A unit right triangle in the z = 0 plane, counter-clockwise seen from +z.
const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

int triangleMesh(GltfBuilder& b, json extraAttributes = json::object(), int material = -1) {
    json primitive = {{"attributes", {{"POSITION", b.addPositions(kTriangle)}}}};
    primitive["attributes"].update(extraAttributes);
    if (material >= 0) primitive["material"] = material;
    return b.addMesh(primitive, "Tri");
}

json quaternion(const glm::vec3& axis, float degrees) {
    const float half = glm::radians(degrees) / 2;
    return {axis.x * std::sin(half), axis.y * std::sin(half), axis.z * std::sin(half), std::cos(half)};
}

TEST(GltfNodes, TranslationRotationScaleAndParent) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = triangleMesh(b);
    const int child = b.addNode({{"mesh", mesh}, {"translation", {1, 2, 3}}, {"rotation", quaternion({0, 0, 1}, 90)},
                                 {"scale", {2, 2, 2}}});
    const int parent = b.addNode({{"translation", {10, 0, 0}}, {"children", {child}}});
    b.setScene({parent});
    b.writeGltf(dir.file("trs.gltf"));
    const SceneDescription scene = loadScene(dir.file("trs.gltf"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& m = scene.meshes[0];
    // (1,0,0): scale -> (2,0,0), 90 deg about z -> (0,2,0), + (1,2,3) -> (1,4,3), + parent -> (11,4,3).
    expectNear(m.positions[0], {11, 2, 3});
    expectNear(m.positions[1], {11, 4, 3});
    expectNear(m.positions[2], {9, 2, 3});  // (0,1,0) -> (0,2,0) -> (-2,0,0) -> (-1,2,3) -> (9,2,3)
    ASSERT_EQ(m.normals.size(), 3u);        // none in the file: computed, +z survives a z rotation
    for (const auto& n : m.normals) expectNear(n, {0, 0, 1});
    EXPECT_EQ(m.name, "node0/Tri/0");
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.tangents.empty());  // no UVs, nothing to derive them from
}

TEST(GltfNodes, MatrixIsColumnMajor) {
    TempDir dir;
    GltfBuilder b;
    b.setScene({b.addNode({{"mesh", triangleMesh(b)}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}})});
    b.writeGltf(dir.file("m.gltf"));
    const Mesh m = loadScene(dir.file("m.gltf")).meshes.at(0);
    expectNear(m.positions[1], {6, 6, 7});
}

TEST(GltfNodes, AllRootNodesWithoutAScene) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = triangleMesh(b);
    const int leaf = b.addNode({{"mesh", mesh}, {"translation", {0, 0, 1}}});
    b.addNode({{"mesh", mesh}, {"children", {leaf}}});
    b.addNode({{"mesh", mesh}, {"translation", {0, 0, 2}}});
    b.writeGltf(dir.file("roots.gltf"));
    const SceneDescription all = loadScene(dir.file("roots.gltf"));
    ASSERT_EQ(all.meshes.size(), 3u);  // nodes 1 and 2 are roots; 0 is reached through 1
    b.setScene({2});
    b.writeGltf(dir.file("one.gltf"));
    const SceneDescription one = loadScene(dir.file("one.gltf"));
    ASSERT_EQ(one.meshes.size(), 1u);
    EXPECT_FLOAT_EQ(one.meshes[0].positions[0].z, 2.0f);
}

TEST(GltfNodes, MirroredTransformKeepsTheFrontAndTheTangentFrame) {
    TempDir dir;
    GltfBuilder b;
    const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {0, 1}};
    const int withFrame = triangleMesh(b, {{"NORMAL", b.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                                           {"TEXCOORD_0", b.addVec2(uvs)},
                                           {"TANGENT", b.addVec4({{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}})}});
    const int bare = triangleMesh(b, {{"TEXCOORD_0", b.addVec2(uvs)}});
    b.setScene({b.addNode({{"mesh", withFrame}, {"scale", {-1, 1, 1}}}),
                b.addNode({{"mesh", bare}, {"scale", {-1, 1, 1}}})});
    b.writeGltf(dir.file("mirror.gltf"));
    const SceneDescription scene = loadScene(dir.file("mirror.gltf"));
    ASSERT_EQ(scene.meshes.size(), 2u);
    for (const Mesh& m : scene.meshes) {
        SCOPED_TRACE(m.name);
        // World positions (0,0,0), (-1,0,0), (0,1,0) are clockwise from +z; the swap makes the
        // geometric normal of the stored winding +z again, agreeing with the file's normal.
        const glm::uvec3 t = m.triangles.at(0);
        const glm::vec3 geometric = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
        expectNear(glm::normalize(geometric), {0, 0, 1});
        expectNear(m.normals[1], {0, 0, 1});
        // u runs along world -x, v along +y: tangent (-1,0,0); n x t = (0,-1,0) is against dp/dv -> w = -1.
        ASSERT_EQ(m.tangents.size(), 3u);
        expectNear(glm::vec3(m.tangents[1]), {-1, 0, 0});
        EXPECT_EQ(m.tangents[1].w, -1.0f);
    }
}

TEST(GltfMeshes, MissingNormalsAreAreaWeighted) {
    TempDir dir;
    GltfBuilder b;
    // Triangle A (0,1,2): normal +z, |cross| = 1. Triangle B (0,3,4): cross((0,0,2),(2,0,0)) = (0,4,0).
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}, {2, 0, 0}};
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(p)}}},
                                               {"indices", b.addIndices({0, 1, 2, 0, 3, 4})}})}})});
    b.writeGltf(dir.file("n.gltf"));
    const Mesh m = loadScene(dir.file("n.gltf")).meshes.at(0);
    expectNear(m.normals[0], glm::vec3(0, 4, 1) / std::sqrt(17.0f));  // (0,0,1) + (0,4,0), normalised
    expectNear(m.normals[1], {0, 0, 1});
    expectNear(m.normals[3], {0, 1, 0});
}

TEST(GltfMeshes, MissingTangentsFollowTheUvs) {
    TempDir dir;
    GltfBuilder b;
    // A 2 x 1 quad in z = 0; three UV layouts.
    const std::vector<glm::vec3> p = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    const auto quad = [&](const std::vector<glm::vec2>& uv) {
        return b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(p)}, {"TEXCOORD_0", b.addVec2(uv)}}},
                                              {"indices", b.addIndices({0, 1, 2, 0, 2, 3})}})}});
    };
    b.setScene({quad({{0, 0}, {1, 0}, {1, 1}, {0, 1}}),    // u along +x, v along +y
                quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}}),    // v flipped: along -y
                quad({{0, 0}, {0, 1}, {1, 1}, {1, 0}})});  // u along +y, v along +x
    b.writeGltf(dir.file("t.gltf"));
    const SceneDescription scene = loadScene(dir.file("t.gltf"));
    ASSERT_EQ(scene.meshes.size(), 3u);
    for (int v = 0; v < 4; ++v) {
        expectNear(glm::vec3(scene.meshes[0].tangents[v]), {1, 0, 0});
        EXPECT_EQ(scene.meshes[0].tangents[v].w, 1.0f);   // n x t = +y = dp/dv
        expectNear(glm::vec3(scene.meshes[1].tangents[v]), {1, 0, 0});
        EXPECT_EQ(scene.meshes[1].tangents[v].w, -1.0f);  // dp/dv = -y
        expectNear(glm::vec3(scene.meshes[2].tangents[v]), {0, 1, 0});
        EXPECT_EQ(scene.meshes[2].tangents[v].w, -1.0f);  // n x t = -x, dp/dv = +x
    }
}

TEST(GltfMeshes, TriangleStripAndFan) {
    TempDir dir;
    GltfBuilder b;
    // Strip over a zigzag p_i = (i / 2, i % 2): triangles (0,1,2), (2,1,3), (2,3,4), all clockwise from +z.
    const std::vector<glm::vec3> zigzag = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    const int strip = b.addMesh({{"attributes", {{"POSITION", b.addPositions(zigzag)}}}, {"mode", 5}});
    // Fan around vertex 0 with 16-bit indices: triangles (1,2,0), (2,3,0), counter-clockwise from +z.
    const std::vector<glm::vec3> rim = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    const std::vector<uint16_t> fanIndices = {0, 1, 2, 3};
    const int fan = b.addMesh({{"attributes", {{"POSITION", b.addPositions(rim)}}},
                               {"indices", b.addAccessor(fanIndices.data(), 8, test::kUnsignedShort, "SCALAR", 4)},
                               {"mode", 6}});
    b.setScene({b.addNode({{"mesh", strip}}), b.addNode({{"mesh", fan}})});
    b.writeGltf(dir.file("sf.gltf"));
    const SceneDescription scene = loadScene(dir.file("sf.gltf"));
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.meshes[0].triangles,
              (std::vector<glm::uvec3>{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}}));
    for (const auto& n : scene.meshes[0].normals) expectNear(n, {0, 0, -1});  // a wrong swap would cancel
    EXPECT_EQ(scene.meshes[1].triangles, (std::vector<glm::uvec3>{{1, 2, 0}, {2, 3, 0}}));
    for (const auto& n : scene.meshes[1].normals) expectNear(n, {0, 0, 1});
}

// EXT_mesh_gpu_instancing: a unit quad placed 9 times in a 3 x 3 grid, 2 m apart, by per-instance
// TRANSLATION; instance 4 (the centre) also turned 90 degrees about z and scaled by 0.5.
int instancedQuads(GltfBuilder& b, const std::vector<glm::vec3>& translations, const std::vector<glm::vec4>& rotations,
                   const std::vector<glm::vec3>& scales) {
    const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(quad)}}},
                                {"indices", b.addIndices({0, 1, 2, 0, 2, 3})}}, "Quad");
    json attributes = {{"TRANSLATION", b.addVec3(translations)}};
    if (!rotations.empty()) attributes["ROTATION"] = b.addVec4(rotations);
    if (!scales.empty()) attributes["SCALE"] = b.addVec3(scales);
    b.useExtension("EXT_mesh_gpu_instancing", true);
    return b.addNode({{"mesh", mesh}, {"translation", {0, 0, -5}},
                      {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}});
}

TEST(GltfMeshes, GpuInstancingPlacesEveryInstanceInTheNodesSpace) {
    TempDir dir;
    GltfBuilder b;
    std::vector<glm::vec3> translations, scales(9, glm::vec3(1.0f));
    std::vector<glm::vec4> rotations(9, glm::vec4(0, 0, 0, 1));
    for (int i = 0; i < 9; ++i) translations.emplace_back(2.0f * float(i % 3), 2.0f * float(i / 3), 0.0f);
    const json q = quaternion({0, 0, 1}, 90);
    rotations[4] = glm::vec4(q[0].get<float>(), q[1].get<float>(), q[2].get<float>(), q[3].get<float>());
    scales[4] = glm::vec3(0.5f);
    b.setScene({instancedQuads(b, translations, rotations, scales)});
    b.writeGltf(dir.file("instanced.gltf"));
    const SceneDescription scene = loadScene(dir.file("instanced.gltf"));
    // One mesh in its own space, placed 9 times: the triangles of one quad, not of 9.
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& m = scene.meshes[0];
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.name, "node0/Quad/0");
    EXPECT_EQ(m.nodePath, std::vector<std::string>{"node0"});  // woven by the node's name, every instance
    ASSERT_TRUE(m.instances);
    ASSERT_EQ(m.instances->size(), 9u);
    const auto placed = [&](int i, int v) { return glm::vec3((*m.instances)[size_t(i)] * glm::vec4(m.positions[size_t(v)], 1.0f)); };
    for (int i = 0; i < 9; ++i) {
        if (i == 4) continue;
        // Corner (1,1,0) of instance i: its translation, then the node's (0,0,-5).
        expectNear(placed(i, 2), translations[size_t(i)] + glm::vec3(1, 1, -5));
    }
    // The centre: (1,0,0) scaled to (0.5,0,0), turned to (0,0.5,0), moved to (2,2.5,-5).
    expectNear(placed(4, 1), {2, 2.5f, -5});
    expectNear(placed(4, 2), {1.5f, 2.5f, -5});  // (1,1,0) -> (0.5,0.5) -> (-0.5,0.5)
    for (const glm::vec3& n : m.normals) expectNear(n, {0, 0, 1});
    // The 9 quads do not overlap: each instance's bounds are apart from every other's.
    for (int i = 0; i < 9; ++i)
        for (int j = i + 1; j < 9; ++j)
            EXPECT_GT(glm::length(placed(i, 0) + placed(i, 2) - placed(j, 0) - placed(j, 2)) / 2, 1.0f) << i << " and " << j;
    // The world box holds every copy, and framing the scene without a camera sees them all.
    const MeshBox box = worldBox(m);
    expectNear(box.lo, {0, 0, -5});
    expectNear(box.hi, {5, 5, -5});
}

// A zero SCALE hides a copy (glTF's way to leave one out): it is dropped, in one warning for the
// node, since it has no inverse for Embree; a node whose copies are all hidden draws nothing.
TEST(GltfMeshes, GpuInstancingDropsZeroScaledCopiesWithOneWarning) {
    TempDir dir;
    GltfBuilder b;
    const std::vector<glm::vec3> scales = {glm::vec3(1), glm::vec3(0), glm::vec3(1, 0, 1), glm::vec3(2)};
    b.setScene({instancedQuads(b, std::vector<glm::vec3>(4), std::vector<glm::vec4>(4, glm::vec4(0, 0, 0, 1)), scales)});
    b.writeGltf(dir.file("hidden.gltf"));
    const SceneDescription scene = loadScene(dir.file("hidden.gltf"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].instances->size(), 2u);
    EXPECT_FLOAT_EQ((*scene.meshes[0].instances)[1][0][0], 2.0f);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_THAT(scene.warnings[0], HasSubstr("node 'node0': 2 of its 4 EXT_mesh_gpu_instancing instances have a zero scale"));
}

TEST(GltfMeshes, GpuInstancingMistakesAndTheLimitNameTheNode) {
    TempDir dir;
    {
        GltfBuilder b;
        b.setScene({instancedQuads(b, std::vector<glm::vec3>(3), std::vector<glm::vec4>(2, glm::vec4(0, 0, 0, 1)), {})});
        b.writeGltf(dir.file("counts.gltf"));
        EXPECT_THAT(loadError(dir.file("counts.gltf")),
                    HasSubstr("node 'node0': EXT_mesh_gpu_instancing: TRANSLATION, ROTATION and SCALE must have one element per instance"));
    }
    {
        GltfBuilder b;
        b.setScene({instancedQuads(b, std::vector<glm::vec3>(2), std::vector<glm::vec4>(2, glm::vec4(0)), {})});
        b.writeGltf(dir.file("zero.gltf"));
        EXPECT_THAT(loadError(dir.file("zero.gltf")), HasSubstr("ROTATION 0 is a zero quaternion"));
    }
    {
        // One instance past the limit, refused from the accessor's count before it is read (a
        // VEC3 accessor of kMaxInstances + 1 elements over a 12-byte view: the count alone).
        GltfBuilder b;
        const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)}}}});
        b.useExtension("EXT_mesh_gpu_instancing", true);
        const int t = b.addVec3(std::vector<glm::vec3>(1));
        b.json()["accessors"][size_t(t)]["count"] = kMaxInstances + 1;
        b.setScene({b.addNode({{"mesh", mesh}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", t}}}}}}}})});
        b.writeGltf(dir.file("many.gltf"));
        EXPECT_THAT(loadError(dir.file("many.gltf")),
                    HasSubstr("node 'node0': EXT_mesh_gpu_instancing TRANSLATION: 4194305 instances bring the file's past "
                              "woven's limit of 4194304"));
    }
    {
        // A copy placed past the coordinate limit, as a vertex would be.
        GltfBuilder b;
        b.setScene({instancedQuads(b, {glm::vec3(0), glm::vec3(2e12f, 0, 0)}, {}, {})});
        b.writeGltf(dir.file("far.gltf"));
        EXPECT_THAT(loadError(dir.file("far.gltf")), HasSubstr("node 'node0': EXT_mesh_gpu_instancing instance 1: it places the mesh's box at"));
    }
}

TEST(GltfMeshes, QuantizedAttributes) {
    TempDir dir;
    GltfBuilder b;
    b.useExtension("KHR_mesh_quantization", true);
    // Normalized SHORT positions, padded to an 8-byte stride as glTF requires for vertex data.
    const int16_t positions[12] = {0, 0, 0, 0, 32767, 0, 0, 0, -32768, 16384, 0, 0};
    const int posView = b.addView(positions, sizeof(positions));
    b.json()["bufferViews"][posView]["byteStride"] = 8;
    b.json()["accessors"].push_back({{"bufferView", posView}, {"componentType", test::kShort}, {"type", "VEC3"},
                                     {"count", 3}, {"normalized", true}, {"min", {-1, 0, 0}}, {"max", {1, 0.5, 0}}});
    const int position = int(b.json()["accessors"].size()) - 1;
    const uint16_t uv16[6] = {0, 65535, 32768, 0, 65535, 65535};
    const uint8_t uv8[6] = {255, 51, 0, 0, 0, 255};  // 4-byte aligned elements are not needed for 2 bytes
    const int8_t normals[12] = {0, 0, 127, 0, -128, 0, 0, 0, 0, 127, 0, 0};
    const int normalView = b.addView(normals, sizeof(normals));
    b.json()["bufferViews"][normalView]["byteStride"] = 4;
    b.json()["accessors"].push_back({{"bufferView", normalView}, {"componentType", test::kByte}, {"type", "VEC3"},
                                     {"count", 3}, {"normalized", true}});
    const int normal = int(b.json()["accessors"].size()) - 1;
    const uint16_t rawUv[6] = {3, 0, 0, 7, 1, 1};
    const auto mesh = [&](int uvAccessor) {
        return b.addMesh({{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uvAccessor}}}});
    };
    const int m16 = mesh(b.addAccessor(uv16, sizeof(uv16), test::kUnsignedShort, "VEC2", 3, true));
    const int m8 = mesh(b.addAccessor(uv8, sizeof(uv8), test::kUnsignedByte, "VEC2", 3, true));
    const int mRaw = mesh(b.addAccessor(rawUv, sizeof(rawUv), test::kUnsignedShort, "VEC2", 3, false));
    const int mNormal = b.addMesh({{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}});
    b.setScene({b.addNode({{"mesh", m16}, {"scale", {2, 2, 2}}}), b.addNode({{"mesh", m8}}), b.addNode({{"mesh", mRaw}}),
                b.addNode({{"mesh", mNormal}})});
    b.writeGltf(dir.file("q.gltf"));
    const SceneDescription scene = loadScene(dir.file("q.gltf"));
    ASSERT_EQ(scene.meshes.size(), 4u);
    const Mesh& q16 = scene.meshes[0];
    // SHORT normalized: c / 32767, with -32768 clamped to -1; then the node's scale 2.
    expectNear(q16.positions[1], {2, 0, 0});
    expectNear(q16.positions[2], {-2, 2 * 16384 / 32767.0f, 0});
    EXPECT_NEAR(q16.uvs[1].x, 32768 / 65535.0f, 1e-7f);
    EXPECT_EQ(q16.uvs[0], glm::vec2(0, 1));
    EXPECT_EQ(q16.uvs[2], glm::vec2(1, 1));
    EXPECT_NEAR(scene.meshes[1].uvs[0].y, 0.2f, 1e-7f);  // 51 / 255
    EXPECT_EQ(scene.meshes[1].uvs[0].x, 1.0f);
    EXPECT_EQ(scene.meshes[2].uvs[0], glm::vec2(3, 0));  // not normalized: the integer itself
    EXPECT_EQ(scene.meshes[2].uvs[1], glm::vec2(0, 7));
    const Mesh& n8 = scene.meshes[3];
    expectNear(n8.normals[0], {0, 0, 1});
    expectNear(n8.normals[1], {-1, 0, 0});  // BYTE -128 -> -1 (clamped)
    expectNear(n8.normals[2], {0, 1, 0});
}

TEST(GltfMeshes, SparseAccessors) {
    TempDir dir;
    GltfBuilder b;
    const int base = b.addPositions(kTriangle);
    const uint8_t index[1] = {1};
    const glm::vec3 value(5, 5, 5);
    b.json()["accessors"][base]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", b.addView(index, 1)}, {"componentType", test::kUnsignedByte}}},
        {"values", {{"bufferView", b.addView(&value, 12)}}}};
    // No buffer view at all: zeros, then every element replaced.
    const uint16_t all[3] = {0, 1, 2};
    const int valuesView = b.addView(kTriangle.data(), 36);
    b.json()["accessors"].push_back({{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 3},
                                     {"min", {0, 0, 0}}, {"max", {1, 1, 0}},
                                     {"sparse", {{"count", 3},
                                                 {"indices", {{"bufferView", b.addView(all, 6)}, {"componentType", test::kUnsignedShort}}},
                                                 {"values", {{"bufferView", valuesView}}}}}});
    const int viewless = int(b.json()["accessors"].size()) - 1;
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", base}}}})}}),
                b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", viewless}}}})}})});
    b.writeGltf(dir.file("sparse.gltf"));
    const SceneDescription scene = loadScene(dir.file("sparse.gltf"));
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.meshes[0].positions, (std::vector<glm::vec3>{{0, 0, 0}, {5, 5, 5}, {0, 1, 0}}));
    EXPECT_EQ(scene.meshes[1].positions, kTriangle);
}

TEST(GltfScene, FirstPerspectiveCamera) {
    TempDir dir;
    GltfBuilder b;
    b.json()["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}}};
    b.setScene({b.addNode({{"camera", 0}}),
                b.addNode({{"camera", 1}, {"translation", {0, 1, 5}}, {"rotation", quaternion({0, 1, 0}, 90)}, {"scale", {3, 3, 3}}}),
                b.addNode({{"camera", 2}})});
    b.writeGltf(dir.file("cam.gltf"));
    const SceneDescription scene = loadScene(dir.file("cam.gltf"));
    ASSERT_TRUE(scene.hasCamera);
    EXPECT_FLOAT_EQ(scene.camera.yfov, 0.5f);  // the orthographic one is skipped, the third one comes later
    EXPECT_FLOAT_EQ(scene.camera.aspect, 1.5f);
    // 90 degrees about +y turns the view direction -z into -x; the node's scale is dropped.
    expectNear(glm::vec3(scene.camera.cameraToWorld * glm::vec4(0, 0, -1, 0)), {-1, 0, 0});
    expectNear(glm::vec3(scene.camera.cameraToWorld * glm::vec4(0, 1, 0, 0)), {0, 1, 0});
    expectNear(glm::vec3(scene.camera.cameraToWorld[3]), {0, 1, 5});
    EXPECT_THAT(scene.warnings.at(0), HasSubstr("orthographic"));
    ASSERT_EQ(scene.cameras.size(), 2u);  // every perspective one, in the order met
    EXPECT_FLOAT_EQ(scene.cameras[1].camera.yfov, 0.9f);
}

// --camera: by index, by the camera's name, by its node's, or auto (as if the file had none).
TEST(GltfScene, CamerasAreChosenByIndexNameOrNode) {
    TempDir dir;
    GltfBuilder b;
    b.json()["cameras"] = {{{"name", "Wide"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}},
                           {{"type", "perspective"}, {"perspective", {{"yfov", 0.3}, {"znear", 0.1}}}}};
    const int mount = b.addNode({{"name", "Mount"}, {"camera", 0}, {"translation", {1, 0, 0}}});
    const int tele = b.addNode({{"camera", 1}});
    b.setScene({b.addNode({{"name", "Rig"}, {"children", {mount}}}), tele, b.addNode({{"mesh", triangleMesh(b)}})});
    b.writeGltf(dir.file("cams.gltf"));
    const SceneDescription loaded = loadScene(dir.file("cams.gltf"));
    ASSERT_EQ(loaded.cameras.size(), 2u);
    EXPECT_EQ(loaded.cameras[0].name, "Wide");
    EXPECT_EQ(loaded.cameras[0].node, "Mount");
    EXPECT_EQ(loaded.cameras[1].name, "camera1");
    EXPECT_EQ(loaded.cameras[1].node, "node1");
    EXPECT_FLOAT_EQ(loaded.camera.yfov, 0.9f);  // the first is the scene's
    const auto chosen = [&](const std::string& choice) {
        SceneDescription scene = loaded;
        chooseCamera(scene, choice);
        return scene;
    };
    EXPECT_FLOAT_EQ(chosen("1").camera.yfov, 0.3f);
    EXPECT_FLOAT_EQ(chosen("node1").camera.yfov, 0.3f);
    EXPECT_FLOAT_EQ(chosen("camera1").camera.yfov, 0.3f);
    const SceneDescription wide = chosen("Mount");
    EXPECT_FLOAT_EQ(wide.camera.yfov, 0.9f);
    expectNear(glm::vec3(wide.camera.cameraToWorld[3]), {1, 0, 0});
    const SceneDescription automatic = chosen("auto");
    EXPECT_FALSE(automatic.hasCamera);
    EXPECT_EQ(sceneCamera(automatic).cameraToWorld, framingCamera(sceneBounds(automatic), Camera{}.yfov).cameraToWorld);
    for (const std::string bad : {"2", "Tele", ""}) {
        try {
            chosen(bad);
            ADD_FAILURE() << "--camera " << bad << " chose a camera";
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), dir.file("cams.gltf") + ": --camera " + bad +
                                                 ": no such camera; its cameras are 0 'Wide' (node 'Mount'), 1 "
                                                 "'camera1' (node 'node1'), or auto");
        }
    }
}

TEST(GltfScene, PunctualLights) {
    TempDir dir;
    GltfBuilder b;
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 4}},
        {{"type", "spot"}, {"intensity", 10}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.3}}}},
        {{"type", "directional"}, {"intensity", 2}}};
    const auto lightNode = [](int light, json extra) {
        extra["extensions"] = {{"KHR_lights_punctual", {{"light", light}}}};
        return extra;
    };
    const int directional = b.addNode(lightNode(2, json::object()));
    b.setScene({b.addNode(lightNode(0, {{"translation", {1, 2, 3}}})),
                b.addNode(lightNode(1, {{"translation", {0, 4, 0}}, {"rotation", quaternion({1, 0, 0}, -90)}})),
                b.addNode({{"rotation", quaternion({0, 1, 0}, 180)}, {"children", {directional}}})});
    b.writeGltf(dir.file("lights.gltf"));
    const SceneDescription scene = loadScene(dir.file("lights.gltf"));
    ASSERT_EQ(scene.lights.size(), 3u);
    const PunctualLight& point = scene.lights[0];
    EXPECT_EQ(point.type, PunctualLight::Type::Point);
    expectNear(point.position, {1, 2, 3});
    // colour x intensity in candela (lux for the sun), / 683 lm/W as Blender's importer converts
    expectNear(point.intensity, glm::vec3(4, 2, 1) / 683.0f);
    const PunctualLight& spot = scene.lights[1];
    EXPECT_EQ(spot.type, PunctualLight::Type::Spot);
    expectNear(spot.direction, {0, -1, 0});  // -90 degrees about x turns -z into -y
    expectNear(spot.intensity, glm::vec3(10.0f / 683.0f));
    EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.1f);
    EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.3f);
    const PunctualLight& sun = scene.lights[2];
    EXPECT_EQ(sun.type, PunctualLight::Type::Directional);
    expectNear(sun.direction, {0, 0, 1});  // the parent's half turn about y
    expectNear(sun.intensity, glm::vec3(2.0f / 683.0f));
}

TEST(GltfMaterials, StandardFallbackAndEmissiveStrength) {
    TempDir dir;
    GltfBuilder b;
    b.useExtension("KHR_materials_emissive_strength");
    const int plain = b.addMaterial({{"name", "Plain"},
                                     {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.6, 0.7, 1}}, {"roughnessFactor", 0.3}, {"metallicFactor", 0.2}}},
                                     {"doubleSided", false}});
    const int lamp = b.addMaterial({{"name", "Lamp"}, {"emissiveFactor", {1, 0.5, 0.25}},
                                    {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}});
    b.setScene({b.addNode({{"mesh", triangleMesh(b, json::object(), plain)}}), b.addNode({{"mesh", triangleMesh(b, json::object(), lamp)}}),
                b.addNode({{"mesh", triangleMesh(b)}})});
    b.writeGltf(dir.file("mat.gltf"));
    const SceneDescription scene = loadScene(dir.file("mat.gltf"));
    ASSERT_EQ(scene.materials.size(), 2u);
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "Plain");
    expectNear(glm::vec3(m.baseColor), {0.5f, 0.6f, 0.7f});
    EXPECT_FLOAT_EQ(m.roughness, 0.3f);
    EXPECT_FLOAT_EQ(m.metallic, 0.2f);
    EXPECT_FALSE(m.doubleSided);
    EXPECT_FALSE(m.woven.has_value());
    EXPECT_FALSE(m.baseColorTexture);
    EXPECT_EQ(m.emission, glm::vec3(0.0f));
    expectNear(scene.materials[1].emission, {4, 2, 1});
    EXPECT_FLOAT_EQ(scene.materials[1].metallic, 1.0f);  // glTF's default metallicFactor
    EXPECT_EQ(scene.meshes[0].material, 0);
    EXPECT_EQ(scene.meshes[1].material, 1);
    EXPECT_EQ(scene.meshes[2].material, -1);
}

TEST(GltfMaterials, WovenFromTheExtensionAndFromExtras) {
    TempDir dir;
    GltfBuilder b;
    b.useExtension("WOVEN_fabric");
    b.addMaterial({{"name", "Cloth"},
                   {"extensions", {{"WOVEN_fabric", {{"pattern", {1, 2, 1}}, {"ex", 300}, {"cy", 0.75},
                                                      {"repeat", {40, 30}}, {"weft_color", {0.1, 0.2, 0.3}}}}}},
                   // The extension wins over extras when both are there.
                   {"extras", {{"woven", {{"pattern", {9, 1, 3}}}}}}});
    b.addMaterial({{"name", "Satin"}, {"extras", {{"woven", {{"pattern", {9, 1, 3}}, {"tile", {"-|", "|-"}}}}, {"other", 1}}}});
    b.setScene({b.addNode({{"mesh", triangleMesh(b, json::object(), 0)}})});
    b.writeGltf(dir.file("woven.gltf"));
    const SceneDescription scene = loadScene(dir.file("woven.gltf"));
    ASSERT_EQ(scene.materials.size(), 2u);
    ASSERT_TRUE(scene.materials[0].woven.has_value());
    const WovenParams& w = *scene.materials[0].woven;
    EXPECT_EQ(w.pattern, glm::ivec3(1, 2, 1));
    EXPECT_EQ(w.ex, 300.0f);
    EXPECT_EQ(w.warp_ex, 300.0f);  // follows ex, as in bsdf-eval
    EXPECT_EQ(w.cy, 0.75f);
    EXPECT_EQ(w.repeat, glm::vec2(40, 30));
    expectNear(w.weft_color, {0.1f, 0.2f, 0.3f});
    EXPECT_EQ(w.ey, WovenParams{}.ey);  // not given: the default
    ASSERT_TRUE(scene.materials[1].woven.has_value());
    EXPECT_EQ(scene.materials[1].woven->pattern, glm::ivec3(9, 1, 3));
    EXPECT_EQ(scene.materials[1].woven->tile, (std::vector<std::string>{"-|", "|-"}));
}

TEST(GltfMaterials, BaseColorTextureFromAFileAndEmbedded) {
    TempDir dir;
    const unsigned char pixels[6] = {255, 0, 0, 0, 128, 255};
    ASSERT_TRUE(stbi_write_png(dir.file("albedo.png").c_str(), 2, 1, 3, pixels, 6));
    GltfBuilder b;
    b.json()["images"] = {{{"uri", "albedo.png"}}};
    b.json()["textures"] = {{{"source", 0}}};
    b.addMaterial({{"name", "A"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {0.5, 1, 1, 1}}}}});
    b.addMaterial({{"name", "B"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    b.setScene({b.addNode({{"mesh", triangleMesh(b, json::object(), 0)}})});
    b.writeGltf(dir.file("tex.gltf"));
    const SceneDescription scene = loadScene(dir.file("tex.gltf"));
    ASSERT_EQ(scene.textures.size(), 1u);  // one image used twice is decoded once
    EXPECT_EQ(scene.materials[0].baseColorTexture.image, 0);
    EXPECT_EQ(scene.materials[1].baseColorTexture.image, 0);
    EXPECT_TRUE(scene.materials[0].baseColorTexture.srgb);  // colour: decoded from sRGB when sampled
    expectNear(glm::vec3(scene.materials[0].baseColor), {0.5f, 1, 1});
    const TextureImage& t = scene.textures[0];
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.bytes.size(), 2u);  // kept as bytes, RGBA with alpha 1
    EXPECT_EQ(t.bytes[0], glm::u8vec4(255, 0, 0, 255));
    EXPECT_EQ(t.bytes[1], glm::u8vec4(0, 128, 255, 255));

    // The same PNG inside a .glb, through a buffer view.
    std::ifstream in(dir.file("albedo.png"), std::ios::binary);
    const std::vector<char> png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    b.json()["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
    b.writeGlb(dir.file("tex.glb"));
    std::filesystem::remove(dir.file("albedo.png"));
    const SceneDescription embedded = loadScene(dir.file("tex.glb"));
    ASSERT_EQ(embedded.textures.size(), 1u);
    EXPECT_EQ(embedded.textures[0].bytes, t.bytes);
}

TEST(GltfMeshes, PointsAndLinesAreSkippedWithAWarning) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = triangleMesh(b);
    b.json()["meshes"][mesh]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
    b.setScene({b.addNode({{"mesh", mesh}})});
    b.writeGltf(dir.file("lines.gltf"));
    const SceneDescription scene = loadScene(dir.file("lines.gltf"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_THAT(scene.warnings[0], HasSubstr("line primitive skipped"));
}

TEST(GltfMeshes, DegenerateTrianglesAreDroppedAndCounted) {
    TempDir dir;
    GltfBuilder b;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    // (0,0,1) repeats an index; (0,1,3) is collinear (zero area).
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(p)}}},
                                               {"indices", b.addIndices({0, 1, 2, 0, 0, 1, 0, 1, 3})}})}})});
    b.writeGltf(dir.file("degenerate.gltf"));
    const SceneDescription scene = loadScene(dir.file("degenerate.gltf"));
    EXPECT_EQ(scene.meshes.at(0).triangles, (std::vector<glm::uvec3>{{0, 1, 2}}));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_THAT(scene.warnings[0], HasSubstr("dropped 2 degenerate"));
}

// Exporters leave a degenerate triangle at each pole of a UV sphere: one line for the file.
TEST(GltfMeshes, DegenerateTrianglesOfManyPrimitivesAreOneWarning) {
    TempDir dir;
    GltfBuilder b;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    const json primitive = {{"attributes", {{"POSITION", b.addPositions(p)}}}, {"indices", b.addIndices({0, 1, 2, 0, 0, 1, 0, 1, 3})}};
    const int sphere = b.addMesh(primitive, "Sphere");
    for (int i = 0; i < 3; ++i) b.json()["meshes"][sphere]["primitives"].push_back(primitive);
    b.setScene({b.addNode({{"mesh", sphere}, {"name", "A"}}), b.addNode({{"mesh", b.addMesh(primitive, "Other")}, {"name", "B"}})});
    b.writeGltf(dir.file("poles.gltf"));
    const SceneDescription scene = loadScene(dir.file("poles.gltf"));
    EXPECT_EQ(scene.meshes.size(), 5u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "dropped 10 degenerate triangles in 5 primitives ('A/Sphere/0', 'A/Sphere/1', 'A/Sphere/2', ...)");
}

TEST(GltfFormats, GlbAndDataUriLoadTheSameAsExternalBuffers) {
    TempDir dir;
    GltfBuilder b;
    b.setScene({b.addNode({{"mesh", triangleMesh(b, {{"TEXCOORD_0", b.addVec2({{0, 0}, {1, 0}, {0, 1}})}})}, {"translation", {1, 0, 0}}})});
    b.writeGltf(dir.file("a.gltf"));
    b.writeGltf(dir.file("b.gltf"), GltfBuilder::Storage::DataUri);
    b.writeGlb(dir.file("c.glb"));
    const SceneDescription a = loadScene(dir.file("a.gltf"));
    for (const char* other : {"b.gltf", "c.glb"}) {
        const SceneDescription s = loadScene(dir.file(other));
        ASSERT_EQ(s.meshes.size(), 1u);
        EXPECT_EQ(s.meshes[0].positions, a.meshes[0].positions);
        EXPECT_EQ(s.meshes[0].uvs, a.meshes[0].uvs);
        EXPECT_EQ(s.source, dir.file(other));
    }
    expectNear(a.meshes[0].positions[1], {2, 0, 0});
}

// ---- broken files ------------------------------------------------------------------------

class BrokenGltf : public ::testing::Test {
protected:
    TempDir dir;
    GltfBuilder b;
    // A valid one-triangle file named `name`, after `edit` changed the document.
    std::string write(const std::string& name, const std::function<void(GltfBuilder&)>& edit = nullptr) {
        if (b.json()["nodes"].empty()) b.setScene({b.addNode({{"mesh", triangleMesh(b)}})});
        if (edit) edit(b);
        const std::string path = dir.file(name);
        if (name.size() > 4 && name.substr(name.size() - 4) == ".glb") b.writeGlb(path);
        else b.writeGltf(path);
        return path;
    }
};

TEST_F(BrokenGltf, MissingFile) {
    const std::string path = dir.file("nothere.gltf");
    EXPECT_THAT(loadError(path), HasSubstr(path + ": no such file"));
}

TEST_F(BrokenGltf, BadJson) {
    const std::string path = dir.file("bad.gltf");
    std::ofstream(path) << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [ {";
    const std::string message = loadError(path);
    EXPECT_THAT(message, HasSubstr(path + ": cannot read glTF: "));
    EXPECT_THAT(message, HasSubstr("parse error"));
}

TEST_F(BrokenGltf, TruncatedGlb) {
    const std::string path = write("t.glb");
    std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
    EXPECT_THAT(loadError(path), HasSubstr(path + ": cannot read glTF binary: "));
}

TEST_F(BrokenGltf, MissingBuffer) {
    const std::string path = write("nobin.gltf");
    std::filesystem::remove(dir.file("nobin.bin"));
    const std::string message = loadError(path);
    EXPECT_THAT(message, HasSubstr(path + ": cannot read glTF: "));
    EXPECT_THAT(message, HasSubstr("not found"));
    EXPECT_THAT(message, HasSubstr("nobin.bin"));
}

// A texture file left out when a folder was copied is drawn without, as glTF viewers and Blender
// do: one warning per file, however many uses share it; --strict makes it an error.
TEST_F(BrokenGltf, MissingTextureFileIsAWarningUnlessStrict) {
    const std::string path = write("notex.gltf", [](GltfBuilder& g) {
        g.json()["images"] = {{{"uri", "gone.png"}}};
        g.json()["textures"] = {{{"source", 0}}};
        g.addMaterial({{"name", "M"},
                       {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {0.5, 0.25, 1, 1}}}},
                       {"normalTexture", {{"index", 0}}}});
    });
    const SceneDescription scene = loadScene(path);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "material 'M'.pbrMetallicRoughness.baseColorTexture: texture file 'gone.png' does not "
                                 "exist (looked in '" + dir.path().string() + "'); drawn without it (--strict makes this an error)");
    const Material& m = scene.materials.at(0);
    EXPECT_FALSE(m.baseColorTexture);  // the factor alone, as a white texture gives
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    EXPECT_FALSE(m.normalTexture);  // the geometry's normal, as a flat normal map gives
    EXPECT_TRUE(scene.textures.empty());

    LoadOptions strict;
    strict.strict = true;
    try {
        loadScene(path, strict);
        ADD_FAILURE() << "--strict loads a missing texture";
    } catch (const SceneError& e) {
        EXPECT_THAT(e.what(), HasSubstr(path + ": material 'M'.pbrMetallicRoughness.baseColorTexture: texture file 'gone.png' does not exist"));
    }
}

// Outside the folder, whether the file is there or not is nothing a file may ask.
TEST_F(BrokenGltf, MissingTextureOutsideTheFolderStaysAnError) {
    const std::string path = write("up.gltf", [](GltfBuilder& g) {
        g.json()["images"] = {{{"uri", "../gone.png"}}};
        g.json()["textures"] = {{{"source", 0}}};
        g.addMaterial({{"name", "M"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    });
    EXPECT_THAT(loadError(path), HasSubstr(path + ": material 'M'.pbrMetallicRoughness.baseColorTexture: cannot read texture file '../gone.png'"));
}

TEST_F(BrokenGltf, CorruptTexture) {
    std::ofstream(dir.file("junk.png")) << "not a png at all";
    const std::string path = write("junktex.gltf", [](GltfBuilder& g) {
        g.json()["images"] = {{{"uri", "junk.png"}}};
        g.json()["textures"] = {{{"source", 0}}};
        g.addMaterial({{"name", "M"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    });
    EXPECT_THAT(loadError(path), HasSubstr("junk.png': the image is an unknown format"));
}

TEST_F(BrokenGltf, NanVertexNamesTheMesh) {
    const std::vector<glm::vec3> p = {{0, 0, 0}, {std::nanf(""), 0, 0}, {0, 1, 0}};
    b.setScene({b.addNode({{"name", "Drape"}, {"mesh", b.addMesh({{"attributes", {{"POSITION", b.addVec3(p)}}}}, "Cloth")}})});
    const std::string path = write("nan.gltf");
    EXPECT_THAT(loadError(path), HasSubstr(path + ": mesh 'Drape/Cloth/0': POSITION holds a NaN or infinite value"));
}

TEST_F(BrokenGltf, IndexOutOfRange) {
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(kTriangle)}}},
                                               {"indices", b.addIndices({0, 1, 7})}})}})});
    const std::string path = write("index.gltf");
    EXPECT_THAT(loadError(path), HasSubstr(path + ": mesh 'node0/mesh0/0': index 7 is out of range (3 vertices)"));
}

TEST_F(BrokenGltf, AccessorOutOfRange) {
    const std::string path = write("range.gltf", [](GltfBuilder& g) { g.json()["accessors"][0]["count"] = 10; });
    // 10 VEC3 floats need 120 bytes; the view holds the 36 of three vertices.
    EXPECT_THAT(loadError(path), HasSubstr(path + ": mesh 'node0/Tri/0': accessor 0: needs 120 bytes of buffer view 0, which has 36"));
}

TEST_F(BrokenGltf, BufferViewPastTheBuffer) {
    const std::string path = write("view.gltf", [](GltfBuilder& g) { g.json()["bufferViews"][0]["byteLength"] = 400; });
    EXPECT_THAT(loadError(path), HasSubstr(path + ":"));
}

TEST_F(BrokenGltf, CompressionExtensionsAreNamed) {
    for (const std::string ext : {"KHR_meshopt_compression"}) {  // Draco and EXT_meshopt are decoded
        GltfBuilder g;
        g.useExtension(ext, true);
        g.setScene({g.addNode({{"mesh", triangleMesh(g)}})});
        const std::string path = dir.file(ext + ".gltf");
        g.writeGltf(path);
        EXPECT_THAT(loadError(path), HasSubstr(path + ": uses " + ext + " mesh compression, which woven does not decode"));
    }
}

TEST_F(BrokenGltf, UnknownRequiredExtension) {
    const std::string path = write("ext.gltf", [](GltfBuilder& g) { g.useExtension("EXT_fancy_things", true); });
    EXPECT_THAT(loadError(path), HasSubstr(path + ": requires the extension EXT_fancy_things"));
}

TEST_F(BrokenGltf, NodeCycle) {
    const std::string path = write("cycle.gltf", [](GltfBuilder& g) { g.json()["nodes"][0]["children"] = {0}; });
    EXPECT_THAT(loadError(path), HasSubstr(path + ": the node hierarchy has a cycle"));
}

TEST_F(BrokenGltf, BadWovenValueNamesMaterialAndField) {
    const std::string path = write("badwoven.gltf", [](GltfBuilder& g) {
        g.addMaterial({{"name", "Cloth"}, {"extensions", {{"WOVEN_fabric", {{"cy", 2.5}}}}}});
        g.json()["meshes"][0]["primitives"][0]["material"] = 0;
    });
    const std::string message = loadError(path);
    EXPECT_THAT(message, HasSubstr(path + ": material 'Cloth', WOVEN_fabric:"));
    EXPECT_THAT(message, HasSubstr("cy"));
    const std::string unknown = write("unknownwoven.gltf", [](GltfBuilder& g) {
        g.json()["materials"][0] = {{"name", "Cloth"}, {"extras", {{"woven", {{"colour", 1}}}}}};
    });
    EXPECT_THAT(loadError(unknown), HasSubstr("material 'Cloth', extras.woven: unknown woven material field 'colour'"));
}

TEST_F(BrokenGltf, MissingPositions) {
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"NORMAL", b.addVec3({{0, 0, 1}})}}}})}})});
    const std::string path = write("nopos.gltf");
    EXPECT_THAT(loadError(path), HasSubstr(path + ": mesh 'node0/mesh0/0' has no POSITION attribute"));
}

TEST(SceneLoader, UnknownFileType) {
    EXPECT_THAT(loadError("model.obj"), HasSubstr("model.obj: unknown scene file type '.obj'"));
}

}  // namespace
}  // namespace woven
