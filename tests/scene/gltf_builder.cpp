#include "gltf_builder.h"

#include <filesystem>
#include <fstream>

namespace woven::test {

namespace {

std::string base64(const std::vector<unsigned char>& data) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < data.size(); i += 3) {
        uint32_t chunk = uint32_t(data[i]) << 16;
        if (i + 1 < data.size()) chunk |= uint32_t(data[i + 1]) << 8;
        if (i + 2 < data.size()) chunk |= data[i + 2];
        out += alphabet[(chunk >> 18) & 63];
        out += alphabet[(chunk >> 12) & 63];
        out += i + 1 < data.size() ? alphabet[(chunk >> 6) & 63] : '=';
        out += i + 2 < data.size() ? alphabet[chunk & 63] : '=';
    }
    return out;
}

void put32(std::ofstream& out, uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

GltfBuilder::GltfBuilder() {
    doc_ = {{"asset", {{"version", "2.0"}}},
            {"buffers", nlohmann::json::array()},
            {"bufferViews", nlohmann::json::array()},
            {"accessors", nlohmann::json::array()},
            {"meshes", nlohmann::json::array()},
            {"nodes", nlohmann::json::array()}};
}

int GltfBuilder::addView(const void* data, size_t bytes) {
    while (bin_.size() % 4) bin_.push_back(0);
    const size_t offset = bin_.size();
    const auto* p = static_cast<const unsigned char*>(data);
    bin_.insert(bin_.end(), p, p + bytes);
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    return int(doc_["bufferViews"].size()) - 1;
}

int GltfBuilder::addAccessor(const void* data, size_t bytes, int componentType, const std::string& type,
                             size_t count, bool normalized) {
    nlohmann::json accessor = {{"bufferView", addView(data, bytes)}, {"componentType", componentType},
                               {"type", type}, {"count", count}};
    if (normalized) accessor["normalized"] = true;
    doc_["accessors"].push_back(accessor);
    return int(doc_["accessors"].size()) - 1;
}

int GltfBuilder::addPositions(const std::vector<glm::vec3>& p) {
    const int index = addVec3(p);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
    doc_["accessors"][index]["min"] = {lo.x, lo.y, lo.z};
    doc_["accessors"][index]["max"] = {hi.x, hi.y, hi.z};
    return index;
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& v) {
    return addAccessor(v.data(), v.size() * sizeof(glm::vec3), kFloat, "VEC3", v.size());
}
int GltfBuilder::addVec2(const std::vector<glm::vec2>& v) {
    return addAccessor(v.data(), v.size() * sizeof(glm::vec2), kFloat, "VEC2", v.size());
}
int GltfBuilder::addVec4(const std::vector<glm::vec4>& v) {
    return addAccessor(v.data(), v.size() * sizeof(glm::vec4), kFloat, "VEC4", v.size());
}
int GltfBuilder::addIndices(const std::vector<uint32_t>& indices) {
    return addAccessor(indices.data(), indices.size() * 4, kUnsignedInt, "SCALAR", indices.size());
}

int GltfBuilder::addMesh(const nlohmann::json& primitive, const std::string& name) {
    nlohmann::json mesh = {{"primitives", {primitive}}};
    if (!name.empty()) mesh["name"] = name;
    doc_["meshes"].push_back(mesh);
    return int(doc_["meshes"].size()) - 1;
}

int GltfBuilder::addNode(const nlohmann::json& extra) {
    doc_["nodes"].push_back(extra.is_null() ? nlohmann::json::object() : extra);
    return int(doc_["nodes"].size()) - 1;
}

void GltfBuilder::setScene(const std::vector<int>& roots) {
    doc_["scenes"] = {{{"nodes", roots}}};
    doc_["scene"] = 0;
}

int GltfBuilder::addMaterial(const nlohmann::json& material) {
    doc_["materials"].push_back(material);
    return int(doc_["materials"].size()) - 1;
}

void GltfBuilder::useExtension(const std::string& name, bool required) {
    doc_["extensionsUsed"].push_back(name);
    if (required) doc_["extensionsRequired"].push_back(name);
}

int GltfBuilder::addFallbackBuffer(size_t bytes) {
    fallbackBuffers_.push_back({{"byteLength", bytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    return int(fallbackBuffers_.size());
}

void GltfBuilder::appendFallbackBuffers(nlohmann::json& doc) const {
    for (const nlohmann::json& buffer : fallbackBuffers_) doc["buffers"].push_back(buffer);
}

void GltfBuilder::writeGltf(const std::string& path, Storage storage) const {
    nlohmann::json doc = doc_;
    if (bin_.empty()) {
        doc.erase("buffers");
    } else if (storage == Storage::DataUri) {
        doc["buffers"] = {{{"byteLength", bin_.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin_)}}};
    } else {
        const std::string binName = std::filesystem::path(path).stem().string() + ".bin";
        const std::string binPath = (std::filesystem::path(path).parent_path() / binName).string();
        std::ofstream(binPath, std::ios::binary).write(reinterpret_cast<const char*>(bin_.data()), bin_.size());
        doc["buffers"] = {{{"byteLength", bin_.size()}, {"uri", binName}}};
    }
    appendFallbackBuffers(doc);
    std::ofstream(path) << doc.dump(1);
}

void GltfBuilder::writeGlb(const std::string& path) const {
    nlohmann::json doc = doc_;
    doc["buffers"] = {{{"byteLength", bin_.size()}}};
    appendFallbackBuffers(doc);
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';
    std::vector<unsigned char> bin = bin_;
    while (bin.size() % 4) bin.push_back(0);
    std::ofstream out(path, std::ios::binary);
    out.write("glTF", 4);
    put32(out, 2);
    put32(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    put32(out, uint32_t(text.size()));
    put32(out, 0x4E4F534A);  // "JSON"
    out.write(text.data(), text.size());
    put32(out, uint32_t(bin.size()));
    put32(out, 0x004E4942);  // "BIN\0"
    out.write(reinterpret_cast<const char*>(bin.data()), bin.size());
}

}  // namespace woven::test
