#pragma once
// A flat rectangle of cloth on y = 0, facing +y, one uv unit a metre (u along +x, v along -z,
// tangents along +u): what `woven export --report` renders and what `woven bake`'s sample file
// holds.
#include "scene_description.h"

namespace woven {

// `size` in metres (and uv units), centred on the origin, with material 0.
Mesh flatCloth(glm::vec2 size, const std::string& name);

}  // namespace woven
