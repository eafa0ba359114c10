#pragma once
// A fingerprint of what a scene renders as: every value of a SceneDescription that reaches a
// pixel (geometry, materials, textures, lights, environment) and the camera it is seen through,
// but none of the names, messages or render hints. Two loads of the same files with the same
// options give the same hash on every machine running the same woven; a change anywhere in the
// glTF, its buffers and images, a draft or an option such as --woven gives another. Parts of a
// frame record it (frame_identity.h) and `woven converge` keys its cached reference by it.
#include <string>

#include "scene_description.h"

namespace woven {

// 16 hex digits (XXH64). A field added to SceneDescription that changes the image belongs here.
std::string sceneHash(const SceneDescription& scene, const Camera& camera);

}  // namespace woven
