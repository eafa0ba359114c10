#pragma once
// EXT_meshopt_compression (the output of gltfpack and glTF-Transform's meshopt): buffer views
// whose bytes are meshoptimizer-encoded in another buffer, decoded with libmeshoptimizer into
// plain views before any accessor reads them.
#include <nlohmann/json.hpp>

namespace tinygltf {
class Model;
}

namespace woven {

// A compressed file's fallback buffers have no bytes (only a byteLength, which may be larger
// than the file): tinygltf refuses them. Gives each an empty stand-in in `document`, whose
// views decodeMeshoptViews later fills; returns whether there was any.
bool stubMeshoptFallbackBuffers(nlohmann::json& document);

// Decodes every view with the extension into a buffer of its own, bounded by
// kMaxDecodedGeometryBytes together with `decodedBytes` (what other decoders have decoded);
// throws DecodingError naming the view.
void decodeMeshoptViews(tinygltf::Model& model, size_t& decodedBytes);

}  // namespace woven
