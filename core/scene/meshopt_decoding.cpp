#include "meshopt_decoding.h"

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "decoded_limits.h"

namespace woven {

namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

// One byte: tinygltf refuses an empty data URI.
constexpr const char* kStandInUri = "data:application/octet-stream;base64,AA==";

// A non-negative integer member of the extension, or `fallback` when absent.
size_t integer(const tinygltf::Value& ext, const char* key, const std::string& what, long long fallback = -1) {
    const tinygltf::Value& v = ext.Get(key);
    if (!ext.Has(key) && fallback >= 0) return size_t(fallback);
    if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0.0) || v.GetNumberAsDouble() > 1e18 ||
        v.GetNumberAsDouble() != double((long long)v.GetNumberAsDouble()))
        throw DecodingError(what + ": " + key + " must be an integer from 0 to 2^31 - 1");  // tinygltf's int
    return size_t(v.GetNumberAsDouble());
}

std::string text(const tinygltf::Value& ext, const char* key, const std::string& fallback) {
    const tinygltf::Value& v = ext.Get(key);
    return v.IsString() ? v.Get<std::string>() : fallback;
}

// meshoptimizer asserts what the format allows rather than reporting it: checked first, so a
// file can never reach an assertion.
void checkLayout(const std::string& mode, const std::string& filter, size_t count, size_t stride, const std::string& what) {
    if (mode == "ATTRIBUTES") {
        if (stride == 0 || stride > 256 || stride % 4 != 0)
            throw DecodingError(what + ": byteStride " + std::to_string(stride) + " must be a multiple of 4 from 4 to 256");
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) throw DecodingError(what + ": byteStride of indices must be 2 or 4");
        if (mode == "TRIANGLES" && count % 3 != 0)
            throw DecodingError(what + ": count " + std::to_string(count) + " of TRIANGLES is not a multiple of 3");
        if (filter != "NONE") throw DecodingError(what + ": indices take no filter (" + filter + ")");
    } else {
        throw DecodingError(what + ": unknown mode '" + mode + "' (ATTRIBUTES, TRIANGLES or INDICES)");
    }
    if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
        throw DecodingError(what + ": the OCTAHEDRAL filter needs byteStride 4 or 8");
    if (filter == "QUATERNION" && stride != 8) throw DecodingError(what + ": the QUATERNION filter needs byteStride 8");
    if (filter != "NONE" && filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL")
        throw DecodingError(what + ": unknown filter '" + filter + "'");
}

}  // namespace

bool stubMeshoptFallbackBuffers(nlohmann::json& document) {
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return false;
    bool stubbed = false;
    for (nlohmann::json& buffer : document["buffers"]) {
        if (!buffer.is_object() || buffer.contains("uri")) continue;
        const nlohmann::json* ext = nullptr;
        if (const auto e = buffer.find("extensions"); e != buffer.end() && e->is_object())
            if (const auto m = e->find(kExtension); m != e->end() && m->is_object()) ext = &*m;
        if (!ext || ext->value("fallback", false) != true) continue;
        buffer["uri"] = kStandInUri;
        buffer["byteLength"] = 1;
        stubbed = true;
    }
    return stubbed;
}

void decodeMeshoptViews(tinygltf::Model& model, size_t& decodedBytes) {
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        const auto found = model.bufferViews[v].extensions.find(kExtension);
        if (found == model.bufferViews[v].extensions.end()) continue;
        const std::string what = std::string(kExtension) + " of buffer view " + std::to_string(v);
        const tinygltf::Value& ext = found->second;
        if (!ext.IsObject()) throw DecodingError(what + " must be a JSON object");  // Get() asserts one
        const size_t source = integer(ext, "buffer", what), offset = integer(ext, "byteOffset", what, 0),
                     length = integer(ext, "byteLength", what), stride = integer(ext, "byteStride", what),
                     count = integer(ext, "count", what);
        const std::string mode = text(ext, "mode", ""), filter = text(ext, "filter", "NONE");
        checkLayout(mode, filter, count, stride, what);
        if (source >= model.buffers.size()) throw DecodingError(what + ": buffer " + std::to_string(source) + " does not exist");
        const std::vector<unsigned char>& compressed = model.buffers[source].data;
        if (offset > compressed.size() || length > compressed.size() - offset)
            throw DecodingError(what + ": bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                                " run past the end of buffer " + std::to_string(source) + " (" +
                                std::to_string(compressed.size()) + " bytes)");
        // Both are at most 2^60 (integer()), so the product is exact in long double.
        const long double decoded = (long double)count * stride, viewLength = model.bufferViews[v].byteLength;
        if (decoded > viewLength)
            throw DecodingError(what + ": " + std::to_string(count) + " elements of " + std::to_string(stride) +
                                " bytes do not fit the view's byteLength " + std::to_string(model.bufferViews[v].byteLength));
        if (viewLength > (long double)(kMaxDecodedGeometryBytes - decodedBytes))
            throw DecodingError(what + ": decodes to more than woven's limit of " +
                                std::to_string(kMaxDecodedGeometryBytes >> 30) + " GiB of compressed geometry per file");
        decodedBytes += model.bufferViews[v].byteLength;

        std::vector<unsigned char> bytes(model.bufferViews[v].byteLength);
        const unsigned char* in = compressed.data() + offset;
        const int status = mode == "ATTRIBUTES" ? meshopt_decodeVertexBuffer(bytes.data(), count, stride, in, length)
                           : mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(bytes.data(), count, stride, in, length)
                                                 : meshopt_decodeIndexSequence(bytes.data(), count, stride, in, length);
        if (status != 0)
            throw DecodingError(what + ": the compressed " + mode + " data is corrupt (meshoptimizer error " +
                                std::to_string(status) + ")");
        if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(bytes.data(), count, stride);
        if (filter == "QUATERNION") meshopt_decodeFilterQuat(bytes.data(), count, stride);
        if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(bytes.data(), count, stride);

        tinygltf::Buffer plain;
        plain.data = std::move(bytes);
        model.buffers.push_back(std::move(plain));
        model.bufferViews[v].buffer = int(model.buffers.size() - 1);
        model.bufferViews[v].byteOffset = 0;
    }
}

}  // namespace woven
