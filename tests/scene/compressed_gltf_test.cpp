// Draco (KHR_draco_mesh_compression) and meshoptimizer (EXT_meshopt_compression) files, written
// here with those libraries' encoders, load as their uncompressed twins do (within the
// quantisation the encoding chose); corrupt or oversized compressed data is refused naming the
// file, and decoded data meets every check plain accessors meet.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "draco_grid.h"
#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "../common/load_error.h"

namespace woven {
namespace {

using test::loadError;

using ::testing::HasSubstr;
using json = nlohmann::json;
using test::GltfBuilder;
using test::TempDir;

using test::Grid;

std::string uncompressed(const TempDir& dir, const Grid& grid) {
    GltfBuilder g;
    g.setScene({g.addNode({{"mesh", g.addMesh({{"attributes", {{"POSITION", g.addPositions(grid.positions)},
                                                                {"NORMAL", g.addVec3(grid.normals)},
                                                                {"TEXCOORD_0", g.addVec2(grid.uvs)}}},
                                               {"indices", g.addIndices(grid.indices)}})}})});
    const std::string path = dir.file("plain.glb");
    g.writeGlb(path);
    return path;
}

std::string dracoFile(const TempDir& dir, const Grid& grid, bool corrupt = false) {
    const std::string path = dir.file(corrupt ? "corrupt_draco.glb" : "draco.glb");
    test::writeDracoGrid(path, grid, corrupt);
    return path;
}

// A meshopt-encoded view: the encoded bytes in the binary buffer, decoded into `fallback`.
struct MeshoptView {
    std::vector<unsigned char> encoded;
    size_t count, stride;
    std::string mode, filter = "NONE";
};
int addMeshoptView(GltfBuilder& g, int fallback, size_t& fallbackOffset, const MeshoptView& m) {
    const int view = g.addView(m.encoded.data(), m.encoded.size());
    json& v = g.json()["bufferViews"][size_t(view)];
    json ext = {{"buffer", 0}, {"byteOffset", v["byteOffset"]}, {"byteLength", m.encoded.size()},
                {"byteStride", m.stride}, {"count", m.count}, {"mode", m.mode}};
    if (m.filter != "NONE") ext["filter"] = m.filter;
    v = {{"buffer", fallback}, {"byteOffset", fallbackOffset}, {"byteLength", m.count * m.stride},
         {"extensions", {{"EXT_meshopt_compression", ext}}}};
    if (m.mode == "ATTRIBUTES") v["byteStride"] = m.stride;
    fallbackOffset += m.count * m.stride;
    return view;
}

MeshoptView vertices(const void* data, size_t count, size_t stride) {
    MeshoptView m{std::vector<unsigned char>(meshopt_encodeVertexBufferBound(count, stride)), count, stride, "ATTRIBUTES"};
    m.encoded.resize(meshopt_encodeVertexBuffer(m.encoded.data(), m.encoded.size(), data, count, stride));
    return m;
}

// The grid through meshoptimizer's encoders: positions and UVs losslessly, normals through the
// octahedral filter in 16 bits, indices as TRIANGLES (or a sequence, when `indices` is given).
// `edit` may change the encoded data or the document before the file is written.
std::string meshoptFile(const TempDir& dir, const std::string& name, Grid grid,
                        const std::function<void(std::vector<MeshoptView>&)>& edit = {}) {
    const size_t n = grid.positions.size();
    std::vector<float> normals4;
    for (const glm::vec3& v : grid.normals) normals4.insert(normals4.end(), {v.x, v.y, v.z, 0.0f});
    std::vector<unsigned char> octahedral(n * 8);
    meshopt_encodeFilterOct(octahedral.data(), n, 8, 16, normals4.data());
    std::vector<MeshoptView> views = {vertices(grid.positions.data(), n, 12), vertices(octahedral.data(), n, 8),
                                      vertices(grid.uvs.data(), n, 8)};
    views[1].filter = "OCTAHEDRAL";
    MeshoptView indices{std::vector<unsigned char>(meshopt_encodeIndexBufferBound(grid.indices.size(), n)),
                        grid.indices.size(), 4, "TRIANGLES"};
    indices.encoded.resize(meshopt_encodeIndexBuffer(indices.encoded.data(), indices.encoded.size(),
                                                     grid.indices.data(), grid.indices.size()));
    views.push_back(indices);
    if (edit) edit(views);

    GltfBuilder g;
    g.useExtension("EXT_meshopt_compression", true);
    size_t decoded = 0;
    for (const MeshoptView& v : views) decoded += v.count * v.stride;
    const int fallback = g.addFallbackBuffer(decoded);
    size_t offset = 0;
    std::vector<int> view;
    for (const MeshoptView& v : views) view.push_back(addMeshoptView(g, fallback, offset, v));
    const auto accessor = [&](int v, int type, const std::string& kind, bool normalized = false) {
        g.json()["accessors"].push_back({{"bufferView", view[size_t(v)]}, {"componentType", type}, {"type", kind},
                                          {"count", views[size_t(v)].count}, {"normalized", normalized}});
        return int(g.json()["accessors"].size() - 1);
    };
    const json primitive = {{"attributes", {{"POSITION", accessor(0, test::kFloat, "VEC3")},
                                            {"NORMAL", accessor(1, test::kShort, "VEC3", true)},
                                            {"TEXCOORD_0", accessor(2, test::kFloat, "VEC2")}}},
                            {"indices", accessor(3, test::kUnsignedInt, "SCALAR")}};
    g.setScene({g.addNode({{"mesh", g.addMesh(primitive)}})});
    const std::string path = dir.file(name);
    g.writeGlb(path);
    return path;
}

// Triangles with each rotated to start at its smallest index: meshopt's index codec may rotate
// a triangle's corners (keeping its winding).
std::vector<glm::uvec3> canonical(std::vector<glm::uvec3> triangles) {
    for (glm::uvec3& t : triangles)
        while (t.x != std::min({t.x, t.y, t.z})) t = glm::uvec3(t.y, t.z, t.x);
    return triangles;
}

void expectTwins(const Mesh& plain, const Mesh& decoded, float positionTolerance, float uvTolerance, float normalDot) {
    ASSERT_EQ(decoded.positions.size(), plain.positions.size());
    EXPECT_EQ(canonical(decoded.triangles), canonical(plain.triangles));
    for (size_t v = 0; v < plain.positions.size(); ++v) {
        EXPECT_LE(glm::length(decoded.positions[v] - plain.positions[v]), positionTolerance) << v;
        EXPECT_LE(glm::length(decoded.uvs[v] - plain.uvs[v]), uvTolerance) << v;
        EXPECT_GE(glm::dot(decoded.normals[v], plain.normals[v]), normalDot) << v;
    }
}

TEST(CompressedGltf, DracoLoadsAsItsUncompressedTwin) {
    TempDir dir;
    const Grid grid;
    const SceneDescription plain = loadScene(uncompressed(dir, grid)), draco = loadScene(dracoFile(dir, grid));
    ASSERT_EQ(draco.meshes.size(), 1u);
    // 14 bits over the grid's 1 m extent are steps of 6e-5 m, 12 bits of UV 2.4e-4, 10-bit
    // normals within 0.2 degrees: each tolerance is a few steps.
    expectTwins(plain.meshes[0], draco.meshes[0], 2e-4f, 1e-3f, 0.9995f);
}

TEST(CompressedGltf, MeshoptLoadsAsItsUncompressedTwin) {
    TempDir dir;
    const Grid grid;
    const SceneDescription plain = loadScene(uncompressed(dir, grid)), meshopt = loadScene(meshoptFile(dir, "m.glb", grid));
    ASSERT_EQ(meshopt.meshes.size(), 1u);
    // The vertex codec is lossless; 16-bit octahedral normals are within 0.01 degrees.
    expectTwins(plain.meshes[0], meshopt.meshes[0], 0.0f, 0.0f, 0.99999f);
}

TEST(CompressedGltf, CorruptDracoDataNamesTheFileAndPrimitive) {
    TempDir dir;
    const std::string path = dracoFile(dir, Grid(), true);
    EXPECT_THAT(loadError(path), HasSubstr(path + ": KHR_draco_mesh_compression of mesh 0 primitive 0: the Draco data is corrupt"));
}

TEST(CompressedGltf, CorruptMeshoptDataNamesTheFileAndView) {
    TempDir dir;
    const std::string path = meshoptFile(dir, "corrupt.glb", Grid(), [](std::vector<MeshoptView>& v) {
        v[0].encoded[0] = 0;  // the vertex codec's version byte
    });
    EXPECT_THAT(loadError(path), HasSubstr(path + ": EXT_meshopt_compression of buffer view 0: the compressed ATTRIBUTES data is corrupt"));
}

TEST(CompressedGltf, DecodedSizeIsBoundedBeforeAllocating) {
    TempDir dir;
    // 2^30 eight-byte elements are 8 GiB, claimed by a few bytes of data.
    const std::string path = meshoptFile(dir, "huge.glb", Grid(), [](std::vector<MeshoptView>& v) { v[2].count = size_t(1) << 30; });
    EXPECT_THAT(loadError(path), HasSubstr(path + ": EXT_meshopt_compression of buffer view 2: decodes to more than woven's limit of 4 GiB"));
}

TEST(CompressedGltf, DecodedDataMeetsTheAccessorChecks) {
    TempDir dir;
    Grid nan;
    nan.positions[5].y = std::nanf("");
    const std::string nanPath = meshoptFile(dir, "nan.glb", nan);
    EXPECT_THAT(loadError(nanPath), HasSubstr(nanPath + ": mesh 'node0/mesh0/0': POSITION holds a NaN or infinite value"));
    Grid outOfRange;
    outOfRange.indices[4] = 999;
    const std::string indexPath = meshoptFile(dir, "index.glb", outOfRange);
    EXPECT_THAT(loadError(indexPath), HasSubstr(indexPath + ": mesh 'node0/mesh0/0': index 999 is out of range (64 vertices)"));
}

}  // namespace
}  // namespace woven
