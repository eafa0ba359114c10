#pragma once
// What a material looks like from afar, on a flat surface: its reflectance f cos(theta_i)
// (theta_i from the shading normal, as the integrators weigh it) averaged over points of a uv
// rectangle, see-through points reflecting nothing, for a fixed set of direction pairs. The bake
// fits its sheen to the woven model's far field and measures its mip levels against it.
#include <vector>

#include "surface_material.h"

namespace woven {

struct DirectionPair {
    glm::vec3 wo, wi;  // unit, above the surface (tangent space: x = +u, y = +v, z = the normal)
};

// 40 views and, for each, 32 light directions, both spread cosine-weighted over the hemisphere
// (a surface in a scene is seen and lit in proportion to the cosine): 1280 pairs, grouped by view.
const std::vector<DirectionPair>& farFieldDirections();

// `points` points of the rectangle [0, uvSize], spread by the R2 low-discrepancy sequence (a grid
// would alias with the weave).
std::vector<glm::dvec2> farFieldPoints(glm::dvec2 uvSize, int points);

// The flat surface's hit at uv: z = 0, normal +z, tangents +u, +v.
SurfaceHit flatHit(glm::dvec2 uv);

// Per direction pair, the mean reflectance over the points.
std::vector<glm::vec3> farField(const SurfaceMaterial& material, const std::vector<glm::dvec2>& points,
                                const std::vector<DirectionPair>& directions);

// sqrt(sum |a - reference|^2 / sum |reference|^2) over pairs and channels.
double relativeRmse(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& reference);

}  // namespace woven
