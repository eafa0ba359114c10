#pragma once
// What files a glTF file may have tinygltf read for it: the buffers and images it names, only
// regular files, of a bounded size, inside the glTF file's folder (unless LoadOptions::anyPath).
// Every file read is noted as an input of the scene.
#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class TinyGLTF;
}

namespace woven {

// A glTF file or one of its buffers: far beyond any asset woven renders, well within memory.
constexpr size_t kMaxGltfFileBytes = size_t(4) << 30;

class GltfFileAccess {
public:
    // For the glTF file `gltfPath`; each file read is appended to `inputFiles`, which must
    // outlive this.
    GltfFileAccess(const std::string& gltfPath, bool anyPath, std::vector<std::string>& inputFiles)
        : gltfPath_(gltfPath), anyPath_(anyPath), inputFiles_(inputFiles) {}

    // Why `path` may not be read ("" when it may): it cannot be resolved, or it is outside the
    // glTF file's folder.
    std::string refusal(const std::string& path) const;
    // Has `reader` read files through this, which must outlive its reading.
    void serve(tinygltf::TinyGLTF& reader);

private:
    std::string gltfPath_;
    bool anyPath_;
    std::vector<std::string>& inputFiles_;
};

// The file a relative URI names, decoded as tinygltf decodes it (%XX, and '+' as a space).
std::string uriFilePath(const std::string& uri);

}  // namespace woven
