#pragma once
// The camera a scene is seen through when nothing else is asked for: its own camera, else one
// that frames its bounds. `woven render` and the previewer both start from sceneCamera(), so a
// final frame and the preview it came from look through the same camera, bit for bit.
#include <glm/glm.hpp>
#include <string>

#include "scene_description.h"

namespace woven {

struct SceneBox {
    glm::vec3 lo{0.0f}, hi{0.0f};
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    float radius() const { return 0.5f * glm::length(hi - lo); }
};
// Bounds of every finite vertex; a unit box at the origin when there are none.
SceneBox sceneBounds(const SceneDescription& scene);

// A camera at `position` looking at `target`, `up` giving the image's vertical (must not be
// parallel to the view direction). The glTF convention: it looks down its -z axis.
Camera lookAt(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float yfov);

// A camera as a woven scene file's "camera" says it. viewOf() is a camera's view (the target one
// unit ahead); cameraOf() is what the scene file's reader makes of a view, so a camera passed
// through both is, bit for bit, the one a scene file saved with that view renders through.
struct CameraView {
    glm::vec3 position{0.0f}, target{0.0f, 0.0f, -1.0f}, up{0.0f, 1.0f, 0.0f};
    float yfovDegrees = 39.6f;
};
CameraView viewOf(const Camera& camera);
Camera cameraOf(const CameraView& view);

// Looks at the whole box from the front (-z), slightly above, the bounding sphere filling the
// vertical field of view with a little margin.
Camera framingCamera(const SceneBox& box, float yfov);

// The scene's camera if it has one, else framingCamera() of its bounds.
Camera sceneCamera(const SceneDescription& scene);

// --camera CHOICE: N (an index into scene.cameras), a camera's name or its node's, or "auto" (the
// scene seen as if it had no camera). Sets scene.camera; throws SceneError naming the cameras
// there are when CHOICE is none of them.
void chooseCamera(SceneDescription& scene, const std::string& choice);

}  // namespace woven
