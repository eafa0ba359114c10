#include "draco_decoding.h"

#include <draco/compression/decode.h>
#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "decoded_limits.h"

namespace woven {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

int intValue(const tinygltf::Value& v) {
    return v.IsNumber() && v.GetNumberAsDouble() >= 0.0 && v.GetNumberAsDouble() < 2147483647.0 ? int(v.GetNumberAsDouble()) : -1;
}

// The bytes of an accessor's elements, tightly packed, or 0 for a type tinygltf does not know.
size_t elementBytes(const tinygltf::Accessor& a) {
    const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    const int components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    return size > 0 && components > 0 ? size_t(size) * size_t(components) : 0;
}

template <typename T>
bool convert(const draco::PointAttribute& attribute, uint32_t points, int components, unsigned char* out) {
    std::vector<T> value(static_cast<size_t>(components));
    for (uint32_t p = 0; p < points; ++p) {
        if (!attribute.ConvertValue<T>(attribute.mapped_index(draco::PointIndex(p)), int8_t(components), value.data()))
            return false;
        std::memcpy(out + size_t(p) * components * sizeof(T), value.data(), components * sizeof(T));
    }
    return true;
}

// The attribute's values for every point in the accessor's own component type, so that
// normalized integers stay normalized when the accessor is read.
bool writeAttribute(const draco::PointAttribute& attribute, const tinygltf::Accessor& accessor, uint32_t points,
                    unsigned char* out) {
    const int components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return convert<int8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convert<uint8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return convert<int16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convert<uint16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convert<uint32_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return convert<float>(attribute, points, components, out);
        default: return false;
    }
}

// A new buffer and a tightly packed view over it, which `accessor` then reads from its start.
void pointAccessorAt(tinygltf::Model& model, tinygltf::Accessor& accessor, std::vector<unsigned char> bytes) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    tinygltf::BufferView view;
    view.buffer = int(model.buffers.size());
    view.byteLength = buffer.data.size();
    model.buffers.push_back(std::move(buffer));
    model.bufferViews.push_back(view);
    accessor.bufferView = int(model.bufferViews.size() - 1);
    accessor.byteOffset = 0;
    accessor.sparse.isSparse = false;
}

void decodePrimitive(tinygltf::Model& model, tinygltf::Primitive& primitive, const tinygltf::Value& ext,
                     const std::string& what, size_t& decodedBytes) {
    if (!ext.IsObject()) throw DecodingError(what + " must be a JSON object");  // Get() asserts one
    const int viewIndex = intValue(ext.Get("bufferView"));
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        throw DecodingError(what + ": bufferView " + std::to_string(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw DecodingError(what + ": bufferView " + std::to_string(viewIndex) + " names no buffer");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw DecodingError(what + ": bufferView " + std::to_string(viewIndex) + " runs past the end of its buffer");
    const tinygltf::Value& ids = ext.Get("attributes");
    if (!ids.IsObject()) throw DecodingError(what + ": attributes must be a JSON object");

    // What the accessors claim, bounded before Draco decodes anything.
    struct Target {
        int accessor, id;
        std::string semantic;
    };
    std::vector<Target> targets;
    long double claimed = 0.0L;
    const auto claim = [&](int accessorIndex, const std::string& semantic, size_t bytesPerElement) {
        if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
            throw DecodingError(what + ": " + semantic + " accessor " + std::to_string(accessorIndex) + " does not exist");
        const tinygltf::Accessor& a = model.accessors[size_t(accessorIndex)];
        if (elementBytes(a) == 0) throw DecodingError(what + ": " + semantic + " accessor has an unknown type");
        claimed += (long double)a.count * (bytesPerElement ? bytesPerElement : elementBytes(a));
    };
    for (const std::string& semantic : ids.Keys()) {
        const auto it = primitive.attributes.find(semantic);
        if (it == primitive.attributes.end()) continue;  // the extension may carry attributes glTF does not name
        const int id = intValue(ids.Get(semantic));
        if (id < 0) throw DecodingError(what + ": the id of " + semantic + " must be an integer >= 0");
        claim(it->second, semantic, 0);
        targets.push_back({it->second, id, semantic});
    }
    if (primitive.indices >= 0) claim(primitive.indices, "indices", sizeof(uint32_t));  // decoded as 32-bit
    if (claimed > (long double)(kMaxDecodedGeometryBytes - decodedBytes))
        throw DecodingError(what + ": its accessors claim more than woven's limit of " +
                            std::to_string(kMaxDecodedGeometryBytes >> 30) + " GiB of compressed geometry per file");
    decodedBytes += size_t(claimed);

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) throw DecodingError(what + ": the Draco data is corrupt (" + decoded.status().error_msg_string() + ")");
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    const uint32_t points = mesh->num_points();

    for (const Target& t : targets) {
        tinygltf::Accessor& accessor = model.accessors[size_t(t.accessor)];
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(uint32_t(t.id));
        if (!attribute) throw DecodingError(what + ": " + t.semantic + "'s Draco attribute " + std::to_string(t.id) + " is not in the data");
        if (accessor.count != points)
            throw DecodingError(what + ": " + t.semantic + " accessor claims " + std::to_string(accessor.count) +
                                " elements, the Draco data has " + std::to_string(points));
        std::vector<unsigned char> bytes(size_t(points) * elementBytes(accessor));
        if (!writeAttribute(*attribute, accessor, points, bytes.data()))
            throw DecodingError(what + ": " + t.semantic + "'s Draco attribute does not convert to its accessor's type");
        pointAccessorAt(model, accessor, std::move(bytes));
    }
    if (primitive.indices >= 0) {
        tinygltf::Accessor& accessor = model.accessors[size_t(primitive.indices)];
        const size_t count = size_t(mesh->num_faces()) * 3;
        if (accessor.count != count)
            throw DecodingError(what + ": the indices accessor claims " + std::to_string(accessor.count) +
                                " indices, the Draco data has " + std::to_string(count));
        std::vector<unsigned char> bytes(count * sizeof(uint32_t));
        for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
            for (int c = 0; c < 3; ++c) {
                const uint32_t index = mesh->face(f)[c].value();
                std::memcpy(bytes.data() + (size_t(f.value()) * 3 + c) * sizeof(uint32_t), &index, sizeof(uint32_t));
            }
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.type = TINYGLTF_TYPE_SCALAR;
        pointAccessorAt(model, accessor, std::move(bytes));
    }
}

}  // namespace

bool standInDracoIndexViews(nlohmann::json& document) {
    if (!document.is_object() || !document.contains("meshes") || !document["meshes"].is_array() ||
        !document.contains("accessors") || !document["accessors"].is_array())
        return false;
    nlohmann::json& accessors = document["accessors"];
    bool changed = false;
    for (const nlohmann::json& mesh : document["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (const nlohmann::json& primitive : mesh["primitives"]) {
            const nlohmann::json* ext = nullptr;
            if (!primitive.is_object()) continue;
            if (const auto e = primitive.find("extensions"); e != primitive.end() && e->is_object())
                if (const auto d = e->find(kExtension); d != e->end() && d->is_object()) ext = &*d;
            const auto indices = primitive.find("indices");
            if (!ext || !ext->contains("bufferView") || indices == primitive.end() || !indices->is_number_unsigned() ||
                indices->get<size_t>() >= accessors.size())
                continue;
            nlohmann::json& accessor = accessors[indices->get<size_t>()];
            if (!accessor.is_object() || accessor.contains("bufferView")) continue;
            accessor["bufferView"] = (*ext)["bufferView"];
            changed = true;
        }
    }
    return changed;
}

void decodeDracoPrimitives(tinygltf::Model& model, size_t& decodedBytes) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const auto it = primitive.extensions.find(kExtension);
            if (it == primitive.extensions.end()) continue;
            decodePrimitive(model, primitive, it->second,
                            std::string(kExtension) + " of mesh " + std::to_string(m) + " primitive " + std::to_string(p),
                            decodedBytes);
        }
}

}  // namespace woven
