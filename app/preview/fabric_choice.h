#pragma once
// A library fabric chosen in the panel for one edit, and what the panel measures of the edited
// material: a weaver's figures (fabric_measures.h) at the thread counts its repeat makes on its
// meshes, with the fabric's yarn counts while the material still has the yarns they gave.
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "fabric_measures.h"
#include "scene_description.h"

namespace woven {

struct ChosenFabric {
    std::string target;  // the edit it was chosen for
    std::string name;
    WovenParams params;  // what it made of the material, on its meshes
    TextileKeys textile;
    std::string wif;  // its draft, if it has one
};

// The library's fabric `name` on the meshes `meshes` of `scene`, read as a scene file's
// {"preset": NAME} is (its thread counts made `repeat` on those meshes); warnings as there.
// Throws std::invalid_argument naming the fabric file or the key.
MaterialJson readFabricMaterial(const std::string& name, std::vector<std::string>& warnings);
ChosenFabric chooseFabric(const std::string& target, const std::string& name, const SceneDescription& scene,
                          const std::vector<size_t>& meshes, std::vector<std::string>& warnings);

// `p` at repeat / (100 x metresPerUv) threads per cm. `chosen` (may be null): its yarn counts
// and fibre while `p` keeps the repeat and yarn widths it gave; otherwise each side weighed from
// its width in cotton, or the chosen fabric's fibre.
FabricMeasures measureOnMesh(const WovenParams& p, const glm::dvec2& metresPerUv, const ChosenFabric* chosen);

}  // namespace woven
