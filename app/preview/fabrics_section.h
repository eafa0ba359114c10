#pragma once
// The panel's fabric controls: the Fabrics menu of the library (fabric_menu.h), the fabric last
// chosen and for which edit, the length per UV unit of each target's meshes (measured once a
// scene), and what a weaver quotes of the edited material on them (fabric_choice.h).
#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fabric_choice.h"
#include "fabric_menu.h"
#include "scene_description.h"

namespace woven {

class FabricsSection {
public:
    // A scene opened: nothing chosen, its meshes not measured yet. The menu stays.
    void reset();

    // The menu for the edit of `target` (made on first use: the window's GL context must be
    // current, as it must be when the section goes); the name of the fabric chosen this frame, or empty.
    std::string drawMenu(const std::string& target);
    // Beneath it: the measures of `p` on `target`'s meshes, where their size is known.
    void drawMeasures(const std::string& target, const WovenParams& p, const SceneDescription& scene,
                      const std::vector<size_t>& meshes);

    // The length per UV unit of `target`'s meshes, `meshes` of `scene` (nullopt: they have no UVs).
    const std::optional<glm::dvec2>& metresPerUv(const std::string& target, const SceneDescription& scene,
                                                 const std::vector<size_t>& meshes);

    // The fabric last chosen, if for the edit of `target`.
    const ChosenFabric* chosenFor(const std::string& target) const;
    // Undo's and redo's: the choice as it was.
    const std::optional<ChosenFabric>& chosen() const { return chosen_; }
    void setChosen(std::optional<ChosenFabric> chosen) { chosen_ = std::move(chosen); }
    // This frame's measures line, empty where the meshes' size is unknown (for the widget map).
    const std::string& measures() const { return measures_; }

private:
    std::unique_ptr<FabricMenu> menu_;
    std::optional<ChosenFabric> chosen_;
    std::map<std::string, std::optional<glm::dvec2>> metresPerUv_;
    std::string measures_;
};

}  // namespace woven
