#include "standard_lobe.h"

#include <algorithm>

namespace woven {

StandardLobe standardLobe(const Material& m) {
    const float alpha = std::max(m.roughness * m.roughness, 1e-4f);

    StandardLobe lobe;
    lobe.exponent = std::clamp(2.0f / (alpha * alpha) - 2.0f, 0.0f, 1e4f);
    lobe.rs = 0.04f + (std::clamp(luminance(m.baseColor), 0.0f, 1.0f) - 0.04f) * m.metallic;
    lobe.diffuse = m.baseColor * (1.0f - m.metallic);
    return lobe;
}

}  // namespace woven
