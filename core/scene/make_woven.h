#pragma once
// Turning loaded materials into woven ones without editing the glTF file: used by scene files
// ("materials") and by the command line (`woven render --woven NAME=...`, `woven preview --woven ...`).
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

// Indices of the materials called `materialName`, or of all materials for "*". Throws SceneError
// (naming scene.source and listing the material names) when no material has that name.
std::vector<int> selectMaterials(const SceneDescription& scene, const std::string& materialName);

// Makes the selected materials woven with `params`; their emission and double-sidedness stay.
void makeWoven(SceneDescription& scene, const std::string& materialName, const WovenParams& params);

// The command line's form, "NAME=JSON" (NAME may be "*"): the JSON parameters apply on top of
// the woven parameters the first selected material already has. Throws SceneError naming
// scene.source and the option.
void applyWovenOption(SceneDescription& scene, const std::string& option);

}  // namespace woven
