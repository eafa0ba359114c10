#include "glb_container.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "scene_loader.h"
#include "untrusted_json.h"

namespace woven {

void checkGlbChunks(const std::vector<unsigned char>& file, const std::string& path) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    if (file.size() < 4 || std::memcmp(file.data(), "glTF", 4) != 0) return;
    if (file.size() < 20) fail("cannot read glTF binary: the file is cut short: " + std::to_string(file.size()) + " bytes, under its 20-byte header");
    uint32_t total = 0;
    std::memcpy(&total, file.data() + 8, 4);
    if (total > file.size())
        fail("cannot read glTF binary: the file is cut short: its header says " + std::to_string(total) + " bytes, the file has " +
             std::to_string(file.size()));
    for (size_t at = 12; at < total;) {
        if (total - at < 8) fail("cannot read glTF binary: the chunk header at byte " + std::to_string(at) + " is cut short");
        uint32_t length = 0;
        std::memcpy(&length, file.data() + at, 4);
        if (length > total - at - 8)
            fail("cannot read glTF binary: the chunk at byte " + std::to_string(at) + " says " + std::to_string(length) +
                 " bytes, past the file's end (" + std::to_string(total - at - 8) + " bytes left)");
        at += 8 + size_t(length);
    }
}

nlohmann::json gltfJson(const std::vector<unsigned char>& file, const std::string& path) {
    std::string_view bytes(reinterpret_cast<const char*>(file.data()), file.size());
    if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
        uint32_t length = 0;
        std::memcpy(&length, bytes.data() + 12, 4);
        bytes = bytes.substr(20, std::min<size_t>(length, bytes.size() - 20));
    }
    try {
        return parseUntrustedJson(bytes);
    } catch (const JsonAsWrittenError& e) {
        throw SceneError(path + ": " + e.what());
    } catch (const std::invalid_argument&) {
        return nlohmann::json();  // tinygltf names what is malformed
    }
}

std::vector<unsigned char> withJson(const std::vector<unsigned char>& file, const nlohmann::json& document) {
    std::string json = document.dump();
    if (file.size() < 20 || std::memcmp(file.data(), "glTF", 4) != 0) return {json.begin(), json.end()};
    uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, file.data() + 12, 4);
    const size_t rest = std::min<size_t>(size_t(20) + jsonLength, file.size());
    json.resize((json.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned, JSON padded with spaces
    std::vector<unsigned char> out(file.begin(), file.begin() + 12);
    const uint32_t length = uint32_t(json.size()), total = uint32_t(12 + 8 + json.size() + (file.size() - rest));
    std::memcpy(out.data() + 8, &total, 4);
    out.insert(out.end(), reinterpret_cast<const unsigned char*>(&length), reinterpret_cast<const unsigned char*>(&length) + 4);
    out.insert(out.end(), file.begin() + 16, file.begin() + 20);  // the chunk type, "JSON"
    out.insert(out.end(), json.begin(), json.end());
    out.insert(out.end(), file.begin() + rest, file.end());
    return out;
}

}  // namespace woven
