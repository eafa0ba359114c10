#pragma once
// What one camera sample gives the film besides its pixel's radiance: the splats that BDPT's
// light paths land on other pixels (t = 1), and the record of what its ray first hit, which the
// render passes average. The integrators make them and the film sums them: in a header of their
// own so that the film, its passes and the denoiser need nothing of the integrators (Embree,
// lights, materials).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace woven {

// A contribution to the pixel containing pRaster, added to the film's splat buffer.
struct Splat {
    glm::vec2 pRaster;
    glm::vec3 L;
};

// What the camera ray of a sample first hit, for the render passes (render_passes.h) that guide
// a denoiser: the BSDF's albedo() (the weave's thread colours included), its shading normal (the
// yarn bump included) and the distance from the camera. Woven's lobes have no delta (specular)
// lobes, so the first hit is the first non-specular one. All zero where the ray hits nothing.
// `direct` is the light that the scene's lights (RenderScene::directPassLights()) send the eye by
// way of the hit, each taken from one fixed point of it and unshadowed: where threads are finer
// than a pixel it follows which yarns a pixel's samples hit as the radiance does, without the
// noise of sampling the lights, and the denoiser's regression fits to it (feature_regression.h).
struct FirstHit {
    glm::vec3 albedo{0.0f}, normal{0.0f};
    float depth = 0.0f;
    glm::vec3 direct{0.0f};
};

}  // namespace woven
