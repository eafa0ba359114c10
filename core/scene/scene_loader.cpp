#include "scene_loader.h"

#include <algorithm>
#include <filesystem>

#include "gltf_loader.h"
#include "scene_file.h"

namespace woven {

SceneDescription loadScene(const std::string& path, const LoadOptions& options) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".gltf" || extension == ".glb") return loadGltf(path, options);
    if (extension == ".json") return loadSceneFile(path, options);
    throw SceneError(path + ": unknown scene file type '" + extension + "' (expected .gltf, .glb or .json)");
}

}  // namespace woven
