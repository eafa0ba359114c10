#pragma once
// What a surface point offers texture lookups: both sets of texture coordinates and the vertex
// colour, interpolated from the mesh (zero uv and white where the mesh has none).
#include <glm/glm.hpp>

#include "scene_description.h"

namespace woven {

struct TexCoords {
    glm::vec2 uv[2] = {glm::vec2(0.0f), glm::vec2(0.0f)};  // TEXCOORD_0, TEXCOORD_1
    glm::vec4 color{1.0f};                                   // COLOR_0, linear RGBA
    bool hasUv = false;  // the mesh has TEXCOORD_0
};

// Interpolated at barycentrics (b1, b2) of triangle `triangle`; non-finite values become 0.
TexCoords interpolateTexCoords(const Mesh& mesh, unsigned triangle, float b1, float b2);

}  // namespace woven
