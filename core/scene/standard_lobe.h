#pragma once
// The standard (non-woven) glTF material as one Ashikhmin-Shirley lobe, for the renderer and
// the previewer alike:
//   alpha = roughness^2 (the glTF/Disney remapping), and the isotropic exponent with the same
//   highlight width as a Beckmann/Blinn lobe of that alpha: e = 2 / alpha^2 - 2, clamped to
//   [0, 1e4] (roughness 1 gives e = 0, a broad lobe; roughness 0 the sharpest allowed);
//   rs = mix(0.04, luminance(base colour), metallic): dielectric F0 of 4 %, metals reflect their
//   colour's brightness (the lobe's Fresnel term is grey);
//   rd = base colour x (1 - metallic), times the base colour texture where there is one
//   (bilinear, repeat wrap, already linear).
#include <glm/glm.hpp>

#include "scene_description.h"

namespace woven {

struct StandardLobe {
    float exponent = 0.0f, rs = 0.04f;
    glm::vec3 diffuse{0.0f};  // before the texture
};

StandardLobe standardLobe(const Material& material);

}  // namespace woven
