#pragma once
// `woven export`: a scene written as a standard glTF 2.0 file that other renderers show as woven
// does (docs/EXPORT.md). Each woven material is replaced by its bake (core/bake), the textures
// scaled so the weave keeps its size on the mesh; meshes, the camera woven sees the scene
// through, punctual lights and emitters are written as they are. What glTF cannot say (the
// environment) is left out with a warning.
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_description.h"
#include "woven_bake.h"

namespace woven {

struct ExportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ExportOptions {
    BakeOptions bake;
    bool keepWoven = false;  // also write each woven material's parameters (WOVEN_fabric)
};

// A bake of one of the scene's woven materials.
struct MaterialBake {
    int material;  // index in the scene
    BakedMaterial baked;
};

// The scene as the exported file holds it: every woven material that a mesh uses replaced by its
// bake (materials with the same parameters share one), its woven parameters kept when
// options.keepWoven. `bakes` (optional) receives the bakes. Throws ExportError naming the scene
// when no mesh is woven.
SceneDescription bakedScene(const SceneDescription& scene, const ExportOptions& options,
                            std::vector<MaterialBake>* bakes = nullptr);

// Bakes and writes the scene to `path` (.glb or .gltf). Returns what the file leaves out or
// approximates, one line each (also the bakes' notes). Throws ExportError (a scene with nothing
// woven, a path that cannot be written: checked before baking); no file is left behind then.
std::vector<std::string> exportScene(const SceneDescription& scene, const std::string& path, const ExportOptions& options,
                                     std::vector<MaterialBake>* bakes = nullptr);

}  // namespace woven
