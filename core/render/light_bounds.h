#pragma once
// What a group of lights can send towards a point, bounded: where they are, how much power they
// emit, and the cone of directions their normals and emission span (pbrt-v4's LightBounds and
// DirectionCone, after Conty Estevez and Kulla 2018). The light BVH (bvh_light_sampler.h) sums
// them up its tree and chooses lights by importance().
#include <glm/glm.hpp>

#include "light.h"

namespace woven {

// Directions within the angle acos(cosTheta) of w; cosTheta -1 is the whole sphere, and
// cosTheta above 1 holds no direction.
struct DirectionCone {
    glm::vec3 w{0.0f, 0.0f, 1.0f};
    float cosTheta = 2.0f;

    bool empty() const { return cosTheta > 1.0f; }
    static DirectionCone entireSphere() { return {glm::vec3(0.0f, 0.0f, 1.0f), -1.0f}; }
};

// The smallest cone holding both.
DirectionCone unionOf(const DirectionCone& a, const DirectionCone& b);

struct LightBounds {
    Bounds bounds;
    float phi = 0.0f;  // the power's luminance, as the power sampler weighs lights
    // The lights' normals lie within cone.cosTheta (theta_o) of cone.w, and each emits within
    // acos(cosThetaE) (theta_e) beyond its normal: pi / 2 for a surface's cosine lobe.
    DirectionCone cone;
    float cosThetaE = 1.0f;
    bool twoSided = false;

    // An upper bound on what these lights could send to p on a surface of normal n, relative to
    // other bounds' (n zero away from surfaces): the power over the squared distance, times the
    // best cosines that the bounds allow at the lights and at p. 0 only where none can reach p.
    float importance(const glm::vec3& p, const glm::vec3& n) const;
};

LightBounds unionOf(const LightBounds& a, const LightBounds& b);

// The bounds of one light; none for infinite lights, which are not in the BVH, and for lights
// of no power.
std::optional<LightBounds> boundsOf(const Light& light);

}  // namespace woven
