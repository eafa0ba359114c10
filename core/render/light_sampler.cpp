#include "light_sampler.h"

#include <algorithm>

namespace woven {

PowerLightSampler::PowerLightSampler(const std::vector<Light>& lights) : count_(int(lights.size())) {
    if (lights.empty()) return;
    std::vector<float> power;
    for (const Light& light : lights) power.push_back(std::max(luminance(light.power()), 0.0f));
    choice_.emplace(power);
}

int PowerLightSampler::sample(float u, float* pmf) const {
    if (!choice_) {
        *pmf = 0.0f;
        return -1;
    }
    return choice_->sampleDiscrete(u, pmf);
}

float PowerLightSampler::pmf(int index) const {
    return choice_ && index >= 0 && index < count_ ? choice_->discretePmf(index) : 0.0f;
}

}  // namespace woven
