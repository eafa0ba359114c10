#pragma once
// One baked texel from the woven model over its footprint. Each point of the footprint is a
// microfacet lobe around a bumped normal (the model's A-S lobe at that point); the texel's glTF
// lobe is fitted to all of them together, LEAN-style (Olano and Baker 2010): the mean normal, and
// the spread of the microfacet normals about it (each point's own lobe plus how far its normal
// is from the others) as an anisotropic GGX's two widths and direction. Spreads add, so the
// sums of a footprint are the sums of its parts: a mip level's texel is fitted from the sums of
// the texels below it, which is averaging in the model rather than in texel space.
#include <glm/glm.hpp>

#include "woven_material.h"

namespace woven {

struct TexelSums {
    double points = 0.0;     // points of the model looked at
    double covered = 0.0;    // of which on a yarn or the backing: not see-through
    glm::dvec3 color{0.0};   // sums over the covered points of: the glTF base colour each asks for
    double rs = 0.0;         //   its specular reflectance
    glm::dvec3 normal{0.0};  //   its bumped normal (tangent space: x = +u, y = +v, z = the surface's)
    glm::dmat2 spread{0.0};  //   n_xy n_xy^T plus its lobe's covariance of microfacet normals in the plane
    glm::dvec3 transmitted{0.0};  //  its yarn's body transmittance T (yarn_transmission.h), 0 for opaque yarns

    // A point of the model: its shading at a flat surface with the tangent frame (+u, +v, n), or
    // nullopt where it is see-through.
    void add(const std::optional<WovenShading>& shading);
    TexelSums& operator+=(const TexelSums& other);
};

// The glTF parameters of a texel (KHR_materials_anisotropy's parametrisation): the GGX alpha is
// roughness^2 across `direction` and mix(roughness^2, 1, anisotropy^2) along it.
struct TexelFit {
    float coverage = 0.0f;     // the fraction of the footprint that is not see-through: alpha
    glm::vec3 baseColor{0.0f};  // linear
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float roughness = 1.0f, anisotropy = 0.0f;
    glm::vec2 direction{1.0f, 0.0f};  // unit, x + y >= 0 (a direction has no sign)
    float rs = 0.04f;
    glm::vec3 transmitted{0.0f};  // the covered points' mean body transmittance T
};

// Throws nothing; a footprint without a covered point gives coverage 0 and the defaults.
TexelFit fitTexel(const TexelSums& sums);

// The fit with one width for renderers without anisotropy: the isotropic lobe of the same peak
// height, alpha = sqrt(alpha_along alpha_across).
TexelFit isotropic(TexelFit fit);

}  // namespace woven
