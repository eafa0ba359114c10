#pragma once
// Which dimensions of a camera sample (sampler.h) each use of a random number takes, so that
// every path vertex draws from dimensions of its own: a low-discrepancy sampler then
// stratifies, say, the second bounce's BSDF directions over a pixel's samples, whatever the
// other vertices did.
#include <cstdint>

namespace woven {

// The uses at one vertex. 2D uses take two dimensions.
enum class SampleUse : uint32_t {
    LightChoice = 0,    // 1D: which light (next-event estimation, BDPT's s = 1)
    LightPoint = 1,     // 2D: the point on it
    BsdfDirection = 3,  // 2D
    BsdfLobe = 5,       // 1D
    Roulette = 6,       // 1D
    CameraPoint = 7,    // 2D: BDPT's t = 1, a light subpath vertex connected to the lens
    LightDirection = 9, // 2D: the direction a light subpath leaves its light
};
constexpr uint32_t kUsesPerVertex = 11;

// Camera subpaths (and the path tracer's paths) and BDPT's light subpaths.
enum class Subpath : uint32_t { Camera = 0, Light = 1 };

constexpr uint32_t kPixelDimension = 0;  // 2D: the position within the pixel

// vertex: 0 for the camera or the light, 1 for the first surface hit on, as BDPT counts them.
constexpr uint32_t sampleDimension(Subpath subpath, int vertex, SampleUse use) {
    return 2 + (2 * uint32_t(vertex) + uint32_t(subpath)) * kUsesPerVertex + uint32_t(use);
}

}  // namespace woven
