#pragma once
// What the denoiser reads of a frame: the noisy mean colour and the variance of that mean, and
// the render passes that guide it (albedo, shading normal, depth, direct light). Plain data,
// row-major, row 0 at the top; a pass left empty is not used.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace woven {

struct DenoiseBuffers {
    int width = 0, height = 0;
    std::vector<glm::vec3> color;     // linear RGB mean per pixel
    std::vector<glm::vec3> variance;  // per channel, the variance of that mean (not of one sample)
    std::vector<glm::vec3> albedo;    // the first non-specular hit's reflectance
    std::vector<glm::vec3> normal;    // unit shading normal
    std::vector<float> depth;         // distance to the first hit; 0 or inf where the ray missed
    std::vector<glm::vec3> direct;    // the light from the lights by way of the first hit (FirstHit::direct)
    std::vector<glm::vec3> directVariance;  // per channel, the variance of that mean (empty: taken as 0)

    size_t pixels() const { return size_t(width) * size_t(height); }
    // A pixel whose colour, variance, albedo, normal or direct light is not finite, whose variance is negative
    // or whose depth is NaN cannot be weighed against its neighbours: the denoiser leaves it as
    // it is and lends it to none.
    bool usable(size_t pixel) const;
};

// Throws std::invalid_argument when a buffer's size is not the frame's (colour and variance are
// required; passes may be empty).
void checkDenoiseBuffers(const DenoiseBuffers& buffers);

}  // namespace woven
