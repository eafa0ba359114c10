#pragma once
// KHR_draco_mesh_compression: primitives whose attributes and indices are one Draco bitstream
// in a buffer view, decoded with libdraco into plain accessors before any accessor is read.
#include <cstddef>
#include <nlohmann/json.hpp>

namespace tinygltf {
class Model;
}

namespace woven {

// tinygltf refuses an indices accessor without a buffer view, which a Draco primitive's has: each
// is given the primitive's Draco view in `document` as a stand-in, which decoding replaces.
// Returns whether there was any.
bool standInDracoIndexViews(nlohmann::json& document);

// Decodes every primitive with the extension: its accessors then point at buffers of their own.
// What the accessors claim is bounded by kMaxDecodedGeometryBytes together with `decodedBytes`
// before decoding, and the decoded counts must equal the claims; throws DecodingError naming
// the mesh and primitive.
void decodeDracoPrimitives(tinygltf::Model& model, size_t& decodedBytes);

}  // namespace woven
