#pragma once
// Writes small glTF files for the loader tests: one binary buffer, accessors built from plain
// arrays, and the JSON document open for the test to fill in. Saved as .gltf with an external
// .bin, as .gltf with an embedded data URI, or as .glb.
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace woven::test {

// glTF component type codes (glTF 2.0 section 3.6.2.2).
enum ComponentType : int {
    kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126
};

class GltfBuilder {
public:
    GltfBuilder();

    nlohmann::json& json() { return doc_; }

    // Appends raw bytes (4-byte aligned) as a new buffer view; returns its index.
    int addView(const void* data, size_t bytes);
    // An accessor over a new buffer view holding `data`.
    int addAccessor(const void* data, size_t bytes, int componentType, const std::string& type, size_t count,
                    bool normalized = false);
    int addPositions(const std::vector<glm::vec3>& p);  // with the min/max the spec requires
    int addVec3(const std::vector<glm::vec3>& v);
    int addVec2(const std::vector<glm::vec2>& v);
    int addVec4(const std::vector<glm::vec4>& v);
    int addIndices(const std::vector<uint32_t>& indices);

    // A mesh with one primitive; returns the mesh index.
    int addMesh(const nlohmann::json& primitive, const std::string& name = "");
    // A node; `extra` is merged into it (translation, rotation, children, camera, ...).
    int addNode(const nlohmann::json& extra);
    // A scene with these root nodes, made the default.
    void setScene(const std::vector<int>& roots);
    int addMaterial(const nlohmann::json& material);
    void useExtension(const std::string& name, bool required = false);
    // A buffer with a byteLength and no bytes, after the binary one: what EXT_meshopt_compression's
    // views decode into. Returns its index.
    int addFallbackBuffer(size_t bytes);

    enum class Storage { ExternalBin, DataUri };
    void writeGltf(const std::string& path, Storage storage = Storage::ExternalBin) const;
    void writeGlb(const std::string& path) const;

private:
    void appendFallbackBuffers(nlohmann::json& doc) const;

    nlohmann::json doc_;
    nlohmann::json fallbackBuffers_ = nlohmann::json::array();
    std::vector<unsigned char> bin_;
};

}  // namespace woven::test
