#pragma once
// The woven scene file (.json, docs/SCENE_FORMAT.md): a glTF file plus what glTF cannot say or
// what the user wants changed without editing it — woven materials, an environment, extra
// lights, a camera and render defaults. Throws SceneError naming the file and the key.
#include <string>

#include "scene_description.h"
#include "scene_loader.h"

namespace woven {

SceneDescription loadSceneFile(const std::string& path, const LoadOptions& options = {});

}  // namespace woven
