#pragma once
// Turning loaded materials into woven ones without editing the glTF file: used by scene files
// ("materials") and by the command line (`woven render --woven NAME=...`, `woven preview --woven ...`).
#include <string>
#include <vector>

#include "material_json.h"

#include "scene_description.h"

namespace woven {

// Indices of the materials called `materialName`, or of all materials for "*". Throws SceneError
// (naming scene.source and listing the material names) when no material has that name.
std::vector<int> selectMaterials(const SceneDescription& scene, const std::string& materialName);

// `read`'s parameters for material `m`: with "scale": "draft", the repeat that puts the draft's
// threads per centimetre on m's meshes. Throws std::invalid_argument when m has no texture
// coordinates to measure or that repeat is out of range.
WovenParams onMaterial(const SceneDescription& scene, int m, const MaterialJson& read);

// Makes the selected materials woven with `params`; their emission and double-sidedness stay.
void makeWoven(SceneDescription& scene, const std::string& materialName, const WovenParams& params);

// The command line's form, "NAME=JSON" (NAME may be "*"): the JSON parameters apply on top of
// the woven parameters the first selected material already has ("wif" relative to the working
// directory; "scale": "draft" measured on each selected material). Throws SceneError naming
// scene.source and the option.
void applyWovenOption(SceneDescription& scene, const std::string& option);

}  // namespace woven
