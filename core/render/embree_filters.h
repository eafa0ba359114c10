#pragma once
// Embree's filter callbacks: what decides, at each candidate hit Embree finds, whether the ray
// stops there. Single-sided surfaces culled for the rays that see their back, and surfaces whose
// material lets rays through at some points (alpha cut-outs, blended alpha, the woven model's
// gaps).
#include <embree3/rtcore.h>

#include <optional>

#include "scene_description.h"
#include "surface_material.h"

namespace woven {

// What an Embree filter callback needs to decide whether a candidate hit lets the ray through.
struct HitFilter {
    const Mesh* mesh;
    const SurfaceMaterial* material;
    bool random;       // the material's answer depends on a random number (blended alpha)
    bool singleSided;  // glTF's doubleSided false: camera rays cull its back (RayKind)
};

// The face of single-sided surfaces a ray passes through: camera rays the back; rays towards the
// camera the faces that are backs seen from it, so that both ways agree.
enum class Cull { Back, Front };

// An intersect context that says what its context filter culls: Embree hands the filter back the
// pointer it was given, so Embree's part comes first.
struct CullContext {
    RTCIntersectContext embree;
    Cull cull = Cull::Back;
};

// The intersect context of a ray: with `cull`, its context filter culls those faces of the
// single-sided surfaces (the scene must have RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION).
CullContext intersectContext(std::optional<Cull> cull);

// Rejects candidate hits at points that let rays through, for intersection and occlusion rays
// alike: the geometry's filter of meshes whose material may let rays through (its user data a
// HitFilter).
void rejectPassThrough(const RTCFilterFunctionNArguments* args);

}  // namespace woven
