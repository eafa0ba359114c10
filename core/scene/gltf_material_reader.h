#pragma once
// glTF 2.0 materials and their textures, read from the file's JSON: the metallic-roughness core,
// the KHR material extensions woven renders (docs/MATERIALS.md), KHR_texture_transform,
// samplers, and woven's own WOVEN_fabric / extras.woven. Each image is decoded once, on first
// use. Throws SceneError naming the file, the material and the key.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

// The encoded bytes of each glTF image that could be read, by image index.
using EncodedImages = std::map<int, std::vector<unsigned char>>;
// The images whose file does not exist (LoadOptions::strict).
using AbsentImages = std::set<int>;

class GltfMaterialReader {
public:
    // A texture of `absent` is dropped with one warning per image, unless `strict`.
    GltfMaterialReader(std::string path, const nlohmann::json& document, const EncodedImages& images,
                       AbsentImages absent, bool strict, std::function<void(const std::string&)> warn);

    // Appends the file's materials to scene.materials and the images they use to scene.textures.
    void read(SceneDescription& scene);

private:
    [[noreturn]] void fail(const std::string& where, const std::string& problem) const;
    Material readMaterial(const nlohmann::json& source, const std::string& name, SceneDescription& scene);
    void readExtensions(const nlohmann::json& extensions, Material& m, const std::string& name, SceneDescription& scene);
    void readSpecularGlossiness(const nlohmann::json& extension, Material& m, const std::string& where, SceneDescription& scene);
    TextureRef readTexture(const nlohmann::json& info, bool srgb, const std::string& where, SceneDescription& scene);
    int imageTexture(int image, const std::string& where, SceneDescription& scene);

    float number(const nlohmann::json& object, const char* key, float fallback, float lo, float hi,
                 const std::string& where) const;
    // `count` (3 or 4) numbers in [0, 1] as RGB(A), white if absent.
    glm::vec4 unitColor(const nlohmann::json& object, const char* key, int count, const std::string& where) const;
    glm::vec3 color3(const nlohmann::json& object, const char* key, glm::vec3 fallback, const std::string& where) const;

    std::string path_;
    const nlohmann::json& document_;
    const EncodedImages& images_;
    AbsentImages absent_;
    bool strict_;
    std::function<void(const std::string&)> warn_;
    std::map<int, int> textureOfImage_;  // glTF image -> index in scene.textures (-1: absent)
};

}  // namespace woven
