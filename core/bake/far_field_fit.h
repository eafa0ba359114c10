#pragma once
// The factors of a baked material that no texel decides, fitted so that its far field
// (far_field.h) comes closest to the woven model's, least squares over the far field's direction
// pairs: a scale of the base colour, KHR_materials_specular's specularFactor and
// KHR_materials_sheen's colour and roughness. The per-texel fits (texel_fit.h) match each
// A-S lobe's width and diffuse albedo; these factors take up what differs between the models
// across angles: A-S's coupled diffuse darkens at grazing angles where Lambert does not, its
// specular term divides by max(n.k1, n.k2) where GGX's divides by both cosines, and the sheen
// layer is glTF's cloth lobe for what the yarns do at a distance.
#include <vector>

#include "scene_description.h"

namespace woven {

struct FarFieldFit {
    float baseScale = 1.0f;  // multiplies the baked base colour
    float specular = 1.0f;   // KHR_materials_specular's specularFactor, [0, 1]
    SheenParams sheen;       // colour 0: no sheen
    double before = 0.0, after = 0.0;  // the far field's relative RMSE with the factors at 1 and fitted
};

// `baked`: the baked material (factors at 1, no sheen) over `textures`, one tile spanning uvSize.
// Sheen roughness from 0.1 to 1 in steps of 0.1, colour from 0 (no sheen, also when `sheen` is
// false) up to 1.
FarFieldFit fitFarField(const WovenParams& params, const Material& baked, const std::vector<TextureImage>& textures,
                        glm::dvec2 uvSize, bool sheen);

}  // namespace woven
