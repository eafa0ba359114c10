#pragma once
// One headless OpenGL context for the whole test process (made on first use), and the preview
// frame of a scene rendered through it, as linear radiance.
#include "headless_gl.h"
#include "preview_renderer.h"

namespace woven::test {

// Creates the context on first call; it stays current until the process exits.
void ensureHeadlessGl();

// The preview frame of `scene` from its own camera, filter on unless told otherwise. With
// `ambient` false the environment lights nothing (it still shows where the cloth is not),
// as in a direct-lighting image. `shadows` as PreviewOptions::shadows. `refined`: the mean of
// the progressive refinement's frames, as a resting window shows it; else its first frame alone.
Image previewRadiance(const SceneDescription& scene, int width, int height, bool filterWeave = true,
                      bool ambient = true, bool shadows = true, bool refined = false);

}  // namespace woven::test
