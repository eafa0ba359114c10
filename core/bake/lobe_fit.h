#pragma once
// How one Ashikhmin-Shirley lobe of the woven model (MODEL.md section 4) becomes glTF's
// metallic-roughness lobe (Lambert under a Fresnel mix, plus GGX): the widths, the diffuse
// reflectance and the Fresnel term. The choices are documented with their errors in docs/EXPORT.md.
namespace woven {

// The GGX alpha as wide as an A-S lobe of exponent e along one axis: the Phong-Beckmann
// correspondence of Walter et al. 2007, alpha = sqrt(2 / (e + 2)); at the peak the two lobes
// then have the same height, sqrt((e_x + 2)(e_y + 2)) / (8 pi) against sqrt((e_x + 1)(e_y + 1)) / (8 pi).
float ggxAlphaForExponent(float e);

// k such that a glTF base colour k R_d reflects as much diffuse light as the A-S diffuse term of
// R_d, both averaged over every pair of directions (cosine-weighted, the bi-hemispherical albedo):
// glTF's diffuse is Lambert weighted by 1 - F(v.h), A-S's is darker at grazing angles. Both scale
// with 1 - rs, so k is the same for every rs: 0.824.
float diffuseScale();

// The IOR whose dielectric F0 ((ior - 1) / (ior + 1))^2 is rs (KHR_materials_ior).
float iorForF0(float rs);

}  // namespace woven
