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
};

LightBounds unionOf(const LightBounds& a, const LightBounds& b);

// A LightBounds as the light BVH's walk reads it, with what does not depend on the point worked
// out once: the box as its bounding sphere, and the cone's sine.
class LightImportance {
public:
    LightImportance() = default;
    explicit LightImportance(const LightBounds& b);

    // An upper bound on what the lights could send to p on a surface of normal n, relative to
    // other bounds' (n zero away from surfaces): the power over the squared distance, times the
    // best cosines that the bounds allow at the lights and at p. 0 only where none can reach p.
    float operator()(const glm::vec3& p, const glm::vec3& n) const;

private:
    glm::vec3 centre_{0.0f}, w_{0.0f, 0.0f, 1.0f};
    float radius2_ = 0.0f;       // the bounding sphere's squared radius
    float minDistance2_ = 0.0f;  // pbrt-v4's floor on the squared distance: half the diagonal
    float phi_ = 0.0f, cosThetaO_ = 1.0f, sinThetaO_ = 0.0f, cosThetaE_ = 1.0f;
    bool twoSided_ = false;
};

// The bounds of one light; none for infinite lights, which are not in the BVH, and for lights
// of no power.
std::optional<LightBounds> boundsOf(const Light& light);

}  // namespace woven
