#include "gltf_file_access.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "file_reading.h"

namespace woven {

namespace {

// Whether it exists at all; readFile then says why a file that does is refused.
bool fileExists(const std::string& path, void*) {
    std::error_code error;
    return std::filesystem::exists(path, error);
}

std::string keepPath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* access) {
    if (const std::string problem = static_cast<GltfFileAccess*>(access)->refusal(path); !problem.empty()) {
        *err = path + ": " + problem;
        return false;
    }
    try {
        *out = readRegularFile(path, kMaxGltfFileBytes);
    } catch (const FileReadError& e) {
        *err = e.what();
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err = "woven does not write through the glTF loader";
    return false;
}

}  // namespace

std::string GltfFileAccess::refusal(const std::string& path) const {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(fs::path(path), error);
    if (error) return "cannot resolve the path";
    if (anyPath_) return "";
    const fs::path folder = fs::weakly_canonical(fs::absolute(fs::path(gltfPath_)).parent_path(), error);
    const auto [end, unused] = std::mismatch(folder.begin(), folder.end(), resolved.begin(), resolved.end());
    if (end != folder.end()) return "is outside the glTF file's folder (" + folder.string() + "; --allow-any-path reads it)";
    return "";
}

void GltfFileAccess::serve(tinygltf::TinyGLTF& reader) {
    const auto read = [](std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self) {
        auto* access = static_cast<GltfFileAccess*>(self);
        if (!readFile(out, err, path, access)) return false;
        access->inputFiles_.push_back(path);
        return true;
    };
    reader.SetFsCallbacks({fileExists, keepPath, read, refuseWrite, this});
}

std::string uriFilePath(const std::string& uri) {
    std::string file;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            file += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            file += uri[i] == '+' ? ' ' : uri[i];
        }
    }
    return file;
}

}  // namespace woven
