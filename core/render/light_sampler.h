#pragma once
// Which light a light sample takes, as pbrt-v4's lightsamplers.h keeps the choice apart from the
// lights: each in proportion to its power's luminance (pbrt-v4's PowerLightSampler), the same
// choice wherever the sample is taken from. BDPT's, whose light subpaths start from no point;
// the path tracer chooses by bvh_light_sampler.h.
#include <optional>
#include <vector>

#include "light.h"
#include "piecewise_constant.h"

namespace woven {

class PowerLightSampler {
public:
    // The lights with their scene bounds set (infinite lights' power depends on them).
    explicit PowerLightSampler(const std::vector<Light>& lights);

    // A light's index for u in [0, 1) and its probability; -1 (and 0) when there are no lights.
    int sample(float u, float* pmf) const;
    float pmf(int index) const;  // 0 for an index outside the lights

private:
    std::optional<PiecewiseConstant1D> choice_;
    int count_ = 0;
};

}  // namespace woven
