#pragma once
// What `woven render`, `woven export`, `woven bake` and `woven share` take as their first argument: a scene (.gltf, .glb, a
// woven scene file), or a bare fabric shown on woven's drape (assets/cloth_drape.glb, seen as
// assets/default_scene.json sees it, in the default studio light): a library fabric's name
// (`woven fabrics`), a fabric file ({"name", "title", "source", "material"}), a woven
// material's JSON file, a WIF draft (at its own threads per cm) or a U3M (docs/EXPORT.md).
#include <string>

#include "scene_description.h"
#include "scene_loader.h"

namespace woven {

// The drape's woven material takes the fabric's name, so a U3M and a share page name the fabric,
// not the mesh it lies on. Throws SceneError naming the argument (a file that is none of these,
// an unknown fabric name) or std::invalid_argument / DraftError for the fabric's own problems.
// `options` are a scene's (a fabric's drape is woven's own file).
SceneDescription loadSceneOrFabric(const std::string& argument, const LoadOptions& options = {});

}  // namespace woven
