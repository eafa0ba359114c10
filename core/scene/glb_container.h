#pragma once
// The container of a glTF file: a .glb's chunks (a 12-byte header, a JSON chunk, a binary one)
// or a .gltf's JSON text. What the loader checks and rewrites of it before tinygltf reads it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace woven {

// A .glb's chunks must lie within the file its header sizes: tinygltf copies a chunk by the
// length the chunk claims, so a file cut short (or a length field out of range) would have it
// read past the end of the buffer. Throws SceneError naming `path`; a .gltf passes.
void checkGlbChunks(const std::vector<unsigned char>& file, const std::string& path);

// The JSON part of the file (the first chunk of a .glb), or null when it cannot be parsed.
// What tinygltf would read other than as written (untrusted_json.h: nesting deeper than woven
// reads, a NUL byte, a key twice, U+0000 in a string; glTF's JSON forbids them) is refused
// here, before tinygltf walks it: SceneError naming `path`.
nlohmann::json gltfJson(const std::vector<unsigned char>& file, const std::string& path);

// The file with its JSON replaced by `document`: a .glb keeps its binary chunk.
std::vector<unsigned char> withJson(const std::vector<unsigned char>& file, const nlohmann::json& document);

}  // namespace woven
