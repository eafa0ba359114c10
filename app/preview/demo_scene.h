#pragma once
// A procedural scene for the previewer when no scene file is given and for tests: a square of
// cloth with gentle folds, a woven material, a key light, a fill light and a dim environment.
#include "scene_description.h"

namespace woven {

// A red and cream twill with 60 elements per UV unit: the cloth the previewer opens with.
WovenParams demoClothParams();

// `resolution` quads per side; the cloth spans [-1, 1] in x and z, folds in y, uv in [0, 1]^2.
SceneDescription wavyClothScene(const WovenParams& material = demoClothParams(), int resolution = 96);

}  // namespace woven
