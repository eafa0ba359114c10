#include "fabrics_section.h"

#include <imgui.h>

#include <stdexcept>

#include "uv_scale.h"
#include "woven_params.h"

namespace woven {

void FabricsSection::reset() {
    chosen_.reset();
    metresPerUv_.clear();
}

std::string FabricsSection::drawMenu(const std::string& target) {
    if (!menu_) menu_ = std::make_unique<FabricMenu>();
    const ChosenFabric* chosen = chosenFor(target);
    return menu_->draw("fabric", chosen ? chosen->name : "");
}

void FabricsSection::drawMeasures(const std::string& target, const WovenParams& p, const SceneDescription& scene,
                                  const std::vector<size_t>& meshes) {
    measures_.clear();
    const std::optional<glm::dvec2>& scale = metresPerUv(target, scene, meshes);
    if (!scale) {
        ImGui::TextDisabled("(its meshes have no UVs to measure the cloth by)");
        return;
    }
    try {
        validate(p);  // the sliders' message below says what is wrong
    } catch (const std::invalid_argument&) {
        return;
    }
    measures_ = describe(measureOnMesh(p, *scale, chosenFor(target)));
    // One figure a line: ImGui wraps within a number ("0." and "16 cm").
    std::string lines = measures_;
    for (size_t at = lines.find(", "); at != std::string::npos; at = lines.find(", ", at)) lines.replace(at, 2, "\n");
    ImGui::TextUnformatted(lines.c_str());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the repeat on its meshes, %.3g x %.3g cm per UV unit; the yarn counts of the fabric chosen "
                          "while its repeat and yarn widths stay, else each side weighed from its width",
                          100.0 * scale->x, 100.0 * scale->y);
}

const std::optional<glm::dvec2>& FabricsSection::metresPerUv(const std::string& target, const SceneDescription& scene,
                                                             const std::vector<size_t>& meshes) {
    auto [scale, first] = metresPerUv_.try_emplace(target);
    if (first) {
        try {
            scale->second = worldLengthPerUv(scene, meshes);
        } catch (const std::invalid_argument&) {  // no UVs: a cloth of no known size
        }
    }
    return scale->second;
}

const ChosenFabric* FabricsSection::chosenFor(const std::string& target) const {
    return chosen_ && chosen_->target == target ? &*chosen_ : nullptr;
}

}  // namespace woven
