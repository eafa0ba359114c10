#pragma once
// The glTF scene around the draped cloth: the cloth itself (material "Cloth" carrying the
// WOVEN_fabric extension), the object it lies on, a ground plane, lights and a camera.
#include <string>

#include "triangle_mesh.h"
#include "woven_params.h"

namespace drape {

enum class Layout {
    Studio,  // ground, a large emissive quad light above the front left, the camera in front
    Room     // the same inside a closed-top room lit only by a small light facing the back
             // wall behind a shade: the cloth sees light only after a bounce
};

struct DrapeScene {
    TriangleMesh cloth;
    TriangleMesh object;
    woven::WovenParams clothMaterial;
    Layout layout = Layout::Studio;
};

// Writes `scene` as a binary glTF at `path` (atomically; throws std::runtime_error on failure).
void writeDrapeScene(const DrapeScene& scene, const std::string& path);

}  // namespace drape
