#pragma once
// What every consumer of a scene needs to hold, checked once: vertices within the coordinate
// limit (coordinate_limits.h), triangles and per-vertex arrays that agree, materials that exist,
// and at least one triangle. The renderer and the previewer both refuse a scene that fails, with
// the same message.
#include "scene_description.h"

namespace woven {

// Throws SceneError naming scene.source and the mesh.
void validateScene(const SceneDescription& scene);

}  // namespace woven
