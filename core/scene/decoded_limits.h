#pragma once
// How much geometry compressed glTF data (KHR_draco_mesh_compression, EXT_meshopt_compression)
// may decode to: a compressed buffer is untrusted input, and a few bytes can claim gigabytes.
#include <cstddef>
#include <stdexcept>

namespace woven {

// The decoded bytes of all of a file's compressed views and primitives together, checked
// against what the file claims before anything is allocated: as much as one buffer may hold.
constexpr size_t kMaxDecodedGeometryBytes = size_t(4) << 30;

// Compressed data that cannot be decoded or claims more than woven decodes; the message says
// which view or primitive and why (the caller adds the file name).
struct DecodingError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace woven
