#pragma once
// glTF 2.0 (.gltf with external or embedded buffers, .glb) to a SceneDescription: world-space
// meshes, materials (woven from the WOVEN_fabric extension or extras.woven), KHR_lights_punctual
// lights and the first perspective camera. docs/SCENE_FORMAT.md lists what is supported and
// what is rejected. Throws SceneError("<file>: <problem>").
#include <string>

#include "scene_description.h"
#include "scene_loader.h"

namespace woven {

SceneDescription loadGltf(const std::string& path, const LoadOptions& options = {});

}  // namespace woven
