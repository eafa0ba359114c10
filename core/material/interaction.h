#pragma once
// Rays and ray-surface hits in world space.
#include <glm/glm.hpp>
#include <limits>

#include "tex_coords.h"

namespace woven {

struct Ray {
    glm::vec3 o{0.0f}, d{0.0f, 0.0f, 1.0f};
    float tMax = std::numeric_limits<float>::infinity();
};

struct SurfaceHit {
    float t = 0.0f;
    glm::vec3 p{0.0f};
    glm::vec3 ng{0.0f, 0.0f, 1.0f};  // unit geometric normal of the front face (winding order)
    glm::vec3 ns{0.0f, 0.0f, 1.0f};  // unit interpolated shading normal, on ng's side
    bool nsFlipped = false;          // the file's normal points against ng (ns is its negation)
    TexCoords tex;
    // Along the mesh's interpolated tangents where it has them, else from the triangle's UVs (zero
    // when degenerate; an arbitrary tangent frame around ng when the mesh has no UVs).
    glm::vec3 dpdu{0.0f}, dpdv{0.0f};
    int mesh = -1, triangle = -1;
    int instance = -1;  // which of an instanced mesh's copies (Mesh::instances), or -1
    int material = -1;
    float pError = 0.0f;  // bound on p's rounding error along ng: how far spawnRay lifts the origin
    // Where spawnRay also moves a ray's origin: by pError towards the triangle's centroid, so that
    // a hit rounded past the edge where two walls meet does not start outside the closed surface.
    // Set with the hit (RenderScene), once for its shadow rays and its next ray; zero for a hit
    // built by hand.
    glm::vec3 towardsCentroid{0.0f};
    // The pixel's footprint at this point in TEXCOORD_0: how uv changes from one pixel to the next
    // along x and y (setUvFootprint(), footprint.h). Zero: no footprint (a point sample); only
    // materials that filter by it (filtersByFootprint()) get one.
    glm::vec2 duvdx{0.0f}, duvdy{0.0f};
};

// A reflection-only BSDF may only connect directions on the same side of the geometric
// surface: this is what keeps shading normals from leaking light (Veach 1997, 5.3).
inline bool sameGeometricSide(const SurfaceHit& hit, const glm::vec3& a, const glm::vec3& b) {
    return glm::dot(a, hit.ng) * glm::dot(b, hit.ng) > 0.0f;
}

}  // namespace woven
