#include "scene_export.h"


#include <algorithm>
#include <filesystem>
#include <map>

#include "gltf_writer.h"
#include "output_path.h"
#include "scene_camera.h"
#include "woven_params_json.h"

namespace woven {

namespace {

// Whether the file could be created: a glTF name that may be an output (output_path.h).
void checkExportName(const std::string& path) {
    namespace fs = std::filesystem;
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension != ".glb" && extension != ".gltf") throw ExportError(path + ": the file name must end in .glb or .gltf (glTF), .u3ma or .u3m (U3M)");
    try {
        checkOutput(path);
    } catch (const FileWriteError& e) {
        throw ExportError(e.what());
    }
}

}  // namespace

SceneDescription bakedScene(const SceneDescription& scene, const ExportOptions& options, std::vector<MaterialBake>* bakes) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const Mesh& mesh : scene.meshes)
        if (mesh.material >= 0 && size_t(mesh.material) < used.size()) used[size_t(mesh.material)] = true;
    SceneDescription out = scene;
    std::map<std::string, std::pair<int, size_t>> bakeOf;  // parameters -> first texture, index in *bakes
    std::vector<MaterialBake> all;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& original = scene.materials[i];
        if (!original.woven || !used[i]) continue;
        const std::string key = paramsToJson(*original.woven).dump();
        auto it = bakeOf.find(key);
        if (it == bakeOf.end()) {
            BakedMaterial baked;
            try {
                baked = bakeWoven(*original.woven, options.bake);
            } catch (const std::invalid_argument& e) {
                throw ExportError(scene.source + ": material '" + original.name + "': " + e.what());
            }
            it = bakeOf.emplace(key, std::make_pair(int(out.textures.size()), all.size())).first;
            for (const TextureImage& t : baked.textures) {
                out.textures.push_back(t);
                out.textures.back().name = original.name + " " + t.name;
            }
            all.push_back({int(i), std::move(baked)});
        }
        Material& m = out.materials[i] = bakedMaterial(original, all[it->second.second].baked, it->second.first);
        if (options.keepWoven) m.woven = original.woven;
    }
    if (all.empty())
        throw ExportError(scene.source + ": no part of the scene is woven, so there is nothing to bake (make parts woven with "
                                         "--woven TARGET=JSON or a scene file's \"materials\")");
    if (bakes) *bakes = std::move(all);
    return out;
}

std::vector<std::string> exportScene(const SceneDescription& scene, const std::string& path, const ExportOptions& options,
                                     std::vector<MaterialBake>* bakes) {
    checkExportName(path);
    std::vector<MaterialBake> made;
    const SceneDescription out = bakedScene(scene, options, &made);
    std::vector<std::string> warnings;
    for (const MaterialBake& b : made)
        for (const std::string& note : b.baked.notes) warnings.push_back("material '" + scene.materials[size_t(b.material)].name + "': " + note);
    const Environment& env = scene.environment;
    if (env.image || env.color != glm::vec3(0.0f))
        warnings.push_back("the scene's environment (" + std::string(env.image ? "an image" : "a uniform colour") +
                           ") cannot be written in core glTF and is left out; its punctual lights and emitters are written");
    try {
        writeGltf(path, out, sceneCamera(scene), warnings);
    } catch (const GltfExportError& e) {
        throw ExportError(e.what());
    }
    if (bakes) *bakes = std::move(made);
    return warnings;
}

}  // namespace woven
