#pragma once
// What the user clicked on in the previewer: a ray from the preview's camera through the cursor,
// traced against core's Embree scene (built on the first pick, again after the geometry
// changes), so a click finds exactly the primitive the renderer would see there.
#include <memory>

#include "render_scene.h"

namespace woven {

class ScenePicker {
public:
    // Forgets the Embree scene; call when the meshes change.
    void reset() { scene_.reset(); }
    // The index in scene.meshes of the primitive under `cursor` (window pixels, (0, 0) the top
    // left corner of a window of `size`) seen by `camera`, or -1 where the ray meets nothing.
    int pick(const SceneDescription& scene, const Camera& camera, glm::ivec2 size, glm::vec2 cursor);

private:
    std::unique_ptr<RenderScene> scene_;
};

}  // namespace woven
