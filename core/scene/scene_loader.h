#pragma once
// Loading a scene from disk: a glTF 2.0 file (.gltf, .glb) or a woven scene file (.json) that
// names a glTF file and makes its materials woven, sets lights, environment and camera
// (docs/SCENE_FORMAT.md). Every failure throws SceneError whose message names the file and
// the problem; nothing is ever half-loaded.
#include <stdexcept>
#include <string>

#include "scene_description.h"

namespace woven {

struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What a scene may read besides its own file.
struct LoadOptions {
    // A glTF file's buffers and images come from its own folder or below it unless this is set:
    // a URI such as "../../.ssh/id_rsa" or an absolute path could otherwise read any file the
    // user can into a render (woven render --allow-any-path).
    bool anyPath = false;
    // A texture whose image file does not exist is drawn without it, with a warning, as glTF
    // viewers and Blender do (a folder copied without one PNG); this makes it an error
    // (woven render --strict). Unreadable or undecodable images are errors either way.
    bool strict = false;
};

SceneDescription loadScene(const std::string& path, const LoadOptions& options = {});

}  // namespace woven
