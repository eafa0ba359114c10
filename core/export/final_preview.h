#pragma once
// A small final frame of a scene for people to look at, not to measure: U3M's preview and the
// share page's poster. The scene's camera (or the one framing it), default light where it has
// none, `spp` samples, denoised, tone-mapped as `woven render` writes a PNG.
#include "scene_description.h"

namespace woven {

// `longerSide` pixels along the frame's longer side, its aspect the scene's render size's.
TextureImage renderFinalPreview(const SceneDescription& scene, int longerSide, int spp);

}  // namespace woven
