#include "draco_grid.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gltf_builder.h"

namespace woven::test {

namespace {
using json = nlohmann::json;

// An accessor with no view, which the decoder fills.
int decodedAccessor(GltfBuilder& g, int componentType, const std::string& type, size_t count) {
    g.json()["accessors"].push_back({{"componentType", componentType}, {"type", type}, {"count", count}});
    return int(g.json()["accessors"].size() - 1);
}
}  // namespace

Grid::Grid() {
    constexpr int n = 8;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / (n - 1), y = float(j) / (n - 1), k = 3.0f;
            positions.emplace_back(x, y, 0.1f * std::sin(k * x));
            normals.push_back(glm::normalize(glm::vec3(-0.1f * k * std::cos(k * x), 0.0f, 1.0f)));
            uvs.emplace_back(x, y);
        }
    for (uint32_t j = 0; j + 1 < n; ++j)
        for (uint32_t i = 0; i + 1 < n; ++i) {
            const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            indices.insert(indices.end(), {a, b, d, a, d, c});
        }
}

void writeDracoGrid(const std::string& path, const Grid& grid, bool corrupt) {
    draco::Mesh mesh;
    const size_t n = grid.positions.size();
    mesh.set_num_points(uint32_t(n));
    const auto add = [&](draco::GeometryAttribute::Type type, int components, const float* values) {
        draco::GeometryAttribute attribute;
        attribute.Init(type, nullptr, int8_t(components), draco::DT_FLOAT32, false, sizeof(float) * components, 0);
        const int id = mesh.AddAttribute(attribute, true, uint32_t(n));
        for (size_t v = 0; v < n; ++v)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(v)), values + v * components);
        return int(mesh.attribute(id)->unique_id());
    };
    const int position = add(draco::GeometryAttribute::POSITION, 3, &grid.positions[0].x);
    const int normal = add(draco::GeometryAttribute::NORMAL, 3, &grid.normals[0].x);
    const int uv = add(draco::GeometryAttribute::TEX_COORD, 2, &grid.uvs[0].x);
    for (size_t t = 0; t < grid.indices.size(); t += 3)
        mesh.AddFace({draco::PointIndex(grid.indices[t]), draco::PointIndex(grid.indices[t + 1]),
                      draco::PointIndex(grid.indices[t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer encoded;
    if (const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &encoded); !status.ok())
        throw std::runtime_error("Draco cannot encode the grid: " + std::string(status.error_msg()));
    std::vector<char> bytes(encoded.data(), encoded.data() + encoded.size());
    if (corrupt) std::fill(bytes.begin(), bytes.begin() + 8, char(0x55));

    GltfBuilder g;
    g.useExtension("KHR_draco_mesh_compression", true);
    const int view = g.addView(bytes.data(), bytes.size());
    const json primitive = {
        {"attributes", {{"POSITION", decodedAccessor(g, kFloat, "VEC3", n)},
                        {"NORMAL", decodedAccessor(g, kFloat, "VEC3", n)},
                        {"TEXCOORD_0", decodedAccessor(g, kFloat, "VEC2", n)}}},
        {"indices", decodedAccessor(g, kUnsignedShort, "SCALAR", grid.indices.size())},
        {"extensions", {{"KHR_draco_mesh_compression",
                         {{"bufferView", view}, {"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}}}}}}};
    g.setScene({g.addNode({{"mesh", g.addMesh(primitive)}})});
    g.writeGlb(path);
}

}  // namespace woven::test
