#include "fabric_menu.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <iostream>

#include "drawdown_image.h"
#include "fabric_choice.h"
#include "fabric_library.h"
#include "image_texture.h"
#include "widget_map.h"

namespace woven {

Image fabricThumbnail(const MaterialJson& fabric, int pixels) {
    const WovenParams& p = fabric.params;
    const WeavePattern weave = WeavePattern::fromParams(p);
    // A library fabric has thread counts, so its repeat of weave and thread lists is known.
    const std::optional<FabricMeasures> m = measureMaterial(fabric);
    const glm::ivec2 repeat = m ? m->repeatThreads : glm::ivec2(weave.width(), weave.height());
    const int cells = std::clamp(std::max(repeat.x, repeat.y), 16, 128);
    return drawdownImage(weave, p.warp_colors.empty() ? std::vector<glm::vec3>{p.warp_color} : p.warp_colors,
                         p.weft_colors.empty() ? std::vector<glm::vec3>{p.weft_color} : p.weft_colors, cells, cells,
                         std::max(1, pixels / cells));
}

FabricMenu::FabricMenu() {
    try {
        for (const std::string& name : fabricNames()) {
            std::vector<std::string> warnings;  // said again when one is chosen
            const MaterialJson material = readFabricMaterial(name, warnings);
            const Fabric fabric = readFabric(name);
            Entry e{name, fabric.title, fabric.source};
            glGenTextures(1, &e.texture);
            entries_.push_back(e);
            // Reflectances as `woven pattern --png` writes them: no exposure, clamped.
            uploadImageTexture(e.texture, fabricThumbnail(material, 128), {0.0f, ToneMap::Clamp});
        }
    } catch (const std::exception& e) {
        error_ = e.what();
        std::cerr << "warning: the Fabrics menu is empty: " << error_ << "\n";
    }
}

FabricMenu::~FabricMenu() {
    for (const Entry& e : entries_) glDeleteTextures(1, &e.texture);
}

std::string FabricMenu::draw(const char* label, const std::string& current) {
    std::string chosen;
    const float thumb = 2.0f * ImGui::GetFrameHeight();
    const ImGuiStyle& style = ImGui::GetStyle();
    // ImGui sizes a combo's list for eight lines of text: room for the whole library instead,
    // within the window.
    const float listHeight = float(entries_.size()) * (thumb + style.ItemSpacing.y) + 2.0f * style.WindowPadding.y;
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(FLT_MAX, std::min(listHeight, 0.8f * ImGui::GetIO().DisplaySize.y)));
    if (ui::BeginCombo(label, current.empty() ? "(choose a fabric)" : current.c_str())) {
        ImGui::PushStyleVar(ImGuiStyleVar_SelectableTextAlign, ImVec2(0.0f, 0.5f));
        for (const Entry& e : entries_) {
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(e.texture)), ImVec2(thumb, thumb));
            ImGui::SameLine();
            if (ui::Selectable(e.name.c_str(), e.name == current, 0, ImVec2(0.0f, thumb))) chosen = e.name;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", e.title.c_str(), e.source.c_str());
        }
        ImGui::PopStyleVar();
        ui::EndCombo();
    }
    if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
    return chosen;
}

}  // namespace woven
