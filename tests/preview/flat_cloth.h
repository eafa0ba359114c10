#pragma once
// The test scene of the GLSL-versus-core comparisons: a flat square on y = 0, x and z in
// [-1, 1], uv = ((x + 1) / 2, (1 - z) / 2), in a woven or any other material, seen from above at
// an angle, lit by a point and a directional light and nothing else, so every pixel's hit point
// and direct lighting can be computed analytically on the CPU.
#include <cstdint>
#include <vector>

#include "scene_description.h"

namespace woven::test {

SceneDescription flatClothScene(const WovenParams& material);
SceneDescription flatScene(const Material& material);
// flatScene's uv square in 4 x 4 texels of value f(x, y), magnified on screen (no mip level but
// the first is used).
template <class F>
TextureImage texture4x4(F f) {
    TextureImage t;
    t.width = t.height = 4;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) t.bytes.push_back(f(x, y));
    return t;
}

// The direction (unit length) of `camera`'s ray through image position (x, y) in pixels of a
// width x height image, row 0 at the top: the preview's projection.
glm::vec3 cameraRayDirection(const Camera& camera, float x, float y, int width, int height);

// Core's direct-lighting image of flatScene: per pixel the mean over n x n stratified sub-pixel
// positions of SceneMaterials::bsdf + Bsdf::eval (the renderer's own path from hit to BSDF)
// times each light's incident radiance and cosine; rays that miss (or pass where the material
// lets them through or reflects nothing: an alpha cut-out, a see-through gap) see the
// environment. `hitMask` (optional) receives 1
// where every sub-pixel position hits a reflecting point, else 0. `jittered`: each stratum at a
// hashed point within it (the same for every run) in place of its centre, so a weave about as
// fine as the strata shows noise that block means average out, not moire that they keep.
Image coreDirectLighting(const SceneDescription& scene, int width, int height, int n,
                         std::vector<uint8_t>* hitMask = nullptr, bool jittered = false);

}  // namespace woven::test
