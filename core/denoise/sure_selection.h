#pragma once
// The per-pixel choice among candidate filters by Stein's unbiased risk estimate (SURE), after
// Rousselle, Manzi and Zwicker 2013 ("Robust denoising using feature and color information") and
// Kalantari and Sen 2013 ("Removing the noise in Monte Carlo rendering with general image
// denoising algorithms"). A stronger filter wins where the light is smooth and its bias small, a
// weaker one where it would blur what the passes do not hold (the satin's float highlights are in
// the shading, not the albedo). For a filter F of a noisy pixel y of variance s^2,
//     SURE = (F - y)^2 - s^2 + 2 s^2 dF/dy
// is an unbiased estimate of (F - truth)^2 without the truth. One pixel's is too noisy to choose
// by, so the estimates are averaged over a box first, and the choice, a 0/1 map per candidate, is
// averaged over the same box, so that neighbouring pixels blend between filters rather than jump.
#include <vector>

#include <glm/vec3.hpp>

namespace woven {

// One channel's SURE: change = F - y, derivative = dF/dy. For non-local means, F is the weighted
// mean of the window with the centre's weight 1 among W, and dF/dy is 1 / W plus how the weights
// move with y (Van De Ville and Kocher 2009; denoiser.cpp). 1 / W alone, the weights held fixed,
// underrates the error of a strict filter, whose weights follow y the most, and on flat noise
// chose the stricter of two filters as often as not (tests/denoise).
inline float steinUnbiasedRisk(float change, float variance, float derivative) {
    return change * change - variance + 2.0f * variance * derivative;
}

// candidates[k][pixel]: each filter's frame; risk[k][pixel]: its SURE, summed over channels.
// Returns per pixel candidates[0] plus, for each other k, the part of the (2 radius + 1)^2 box
// around the pixel where k had the least box-averaged risk times its difference to candidate 0:
// where the candidates agree the pixel is candidate 0's exactly. The box is cut at the frame's
// edge.
std::vector<glm::vec3> selectBySure(int width, int height, const std::vector<std::vector<glm::vec3>>& candidates,
                                    const std::vector<std::vector<float>>& risk, int radius);

}  // namespace woven
