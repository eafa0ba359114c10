#pragma once
// The material being tuned, saved into a woven scene file (docs/SCENE_FORMAT.md) and read back,
// through core's paramsToJson / paramsFromJson. Errors throw std::runtime_error naming the file.
#include <string>

#include "woven_params.h"

namespace woven {

// Sets materials.<materialName> of the scene file at `path` to `params`, keeping everything else
// in it. A file that does not exist yet becomes a scene file naming `gltf` (as given); with no
// glTF (the procedural cloth) it becomes the bare parameter object. Written atomically.
void saveMaterial(const std::string& path, const std::string& materialName, const WovenParams& params,
                  const std::string& gltf);

// From a scene file (its materials."*", then materials.<materialName>, on top of `base`) or a
// bare parameter object.
WovenParams loadMaterial(const std::string& path, const std::string& materialName, const WovenParams& base);

}  // namespace woven
