// The panel's Selection and Material sections (the sliders generated from wovenParamTable(),
// presets, saving and loading, the draft's file), and the Draft window beside the panel.
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <iostream>
#include <string>

#include "draft_material.h"
#include "material_file.h"
#include "preview_window_impl.h"
#include "uv_scale.h"
#include "weave_presets.h"
#include "woven_params.h"

namespace woven {

// The Fabrics menu, and what a weaver quotes of the edited material where its meshes' size is known.
void PreviewWindow::drawFabricControls(WovenParams& p) {
    if (!fabricMenu_) fabricMenu_ = std::make_unique<FabricMenu>();
    const std::string target = edits_->edits()[size_t(editIndex_)].target;
    const auto chosenHere = [&] { return chosenFabric_ && chosenFabric_->target == target ? &*chosenFabric_ : nullptr; };
    if (const std::string name = fabricMenu_->draw("fabric", chosenHere() ? chosenHere()->name : ""); !name.empty()) {
        try {
            std::vector<std::string> warnings;
            ChosenFabric chosen = chooseFabric(target, name, scene(), edits_->meshesOf(target), warnings);
            p = chosen.params;
            presetIndex_ = -1;
            showFinal_ = false;  // the rendered frame is of the old cloth
            showDraftOf(chosen.wif, warnings);
            chosenFabric_ = std::move(chosen);
            status_ = "fabric " + name + (warnings.empty() ? "" : " (" + warnings.front() + ")");
            for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    measuresLine_.clear();
    const std::optional<glm::dvec2>& scale = metresPerUvOf(target);
    if (!scale) {
        ImGui::TextDisabled("(its meshes have no UVs to measure the cloth by)");
        return;
    }
    try {
        validate(p);  // the sliders' message below says what is wrong
    } catch (const std::invalid_argument&) {
        return;
    }
    measuresLine_ = describe(measureOnMesh(p, *scale, chosenHere()));
    // One figure a line: ImGui wraps within a number ("0." and "16 cm").
    std::string lines = measuresLine_;
    for (size_t at = lines.find(", "); at != std::string::npos; at = lines.find(", ", at)) lines.replace(at, 2, "\n");
    ImGui::TextUnformatted(lines.c_str());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the repeat on its meshes, %.3g x %.3g cm per UV unit; the yarn counts of the fabric chosen "
                          "while its repeat and yarn widths stay, else each side weighed from its width",
                          100.0 * scale->x, 100.0 * scale->y);
}

void PreviewWindow::showDraftOf(const std::string& wif, std::vector<std::string>& warnings) {
    if (wif.empty()) {
        if (draftEdit_ == editIndex_) draft_.reset();
        return;
    }
    draft_ = DraftEditor::open(wif, warnings);
    draftEdit_ = editIndex_;
    copyToBuffer(draftPath_, wif);
}

void PreviewWindow::drawMaterialControls(WovenParams& p) {
    drawFabricControls(p);
    const auto& presets = weavePresets();
    const char* presetName = presetIndex_ >= 0 ? presets[presetIndex_].name.c_str() : "(custom)";
    if (ui::BeginCombo("weave preset", presetName)) {
        for (size_t i = 0; i < presets.size(); ++i)
            if (ui::Selectable(presets[i].name.c_str(), int(i) == presetIndex_)) {
                presetIndex_ = int(i);
                applyPreset(presets[i], p);
            }
        ui::EndCombo();
    }
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) continue;  // the tile and the per-thread lists: the draft view
        char* field = reinterpret_cast<char*>(&p) + info.offset;
        ImGui::PushID(info.name);
        const ImGuiSliderFlags flags = info.logScale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
        switch (info.type) {
        case ParamType::Float:
            ui::SliderFloat(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Int:
            ui::SliderInt(info.label, reinterpret_cast<int*>(field), int(info.min), int(info.max));
            break;
        case ParamType::Vec2:
            ui::SliderFloat2(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Vec3:
            ui::ColorEdit3(info.label, reinterpret_cast<float*>(field), ImGuiColorEditFlags_Float);
            break;
        case ParamType::IVec3: {
            int* v = reinterpret_cast<int*>(field);
            if (ui::InputInt3(info.label, v)) {
                for (int c = 0; c < 3; ++c) v[c] = std::clamp(v[c], int(info.min), int(info.max));
                p.tile.clear();  // an edited (i, j, k) replaces a hand-drawn tile
                presetIndex_ = -1;
            }
            break;
        }
        default: break;
        }
        // The scene-file key and its meaning, so what the panel tunes can be written by hand.
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", info.name, info.description);
        ImGui::PopID();
    }
    try {
        validate(p);
    } catch (const std::exception& e) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", e.what());
    }

    ui::InputText("scene file", materialPath_, sizeof materialPath_);
    const std::string& target = edits_->edits()[size_t(editIndex_)].target;
    if (ui::Button("Save materials")) {
        // Every edit under its target, as a scene file's "materials" says it.
        try {
            const bool gltf = hasExtension(scenePath_, ".gltf") || hasExtension(scenePath_, ".glb");
            for (const WovenEdit& e : edits_->edits()) saveMaterial(materialPath_, e.target, e.params, gltf ? scenePath_ : "");
            status_ = std::string("saved ") + materialPath_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ui::Button("Load material")) {
        try {
            std::vector<std::string> warnings;
            const MaterialJson read = loadMaterial(materialPath_, target, p, warnings);
            p = scaledToMeshes(read, scene(), edits_->meshesOf(target), warnings);
            presetIndex_ = -1;
            if (chosenFabric_ && chosenFabric_->target == target) chosenFabric_.reset();
            status_ = std::string("loaded ") + materialPath_;
            if (!read.wif.empty()) showDraftOf(read.wif, warnings);
            for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    drawDraftControls(p);
}

void PreviewWindow::drawDraftControls(WovenParams& p) {
    ImGui::Separator();
    ui::InputText("draft file", draftPath_, sizeof draftPath_);
    if (ui::Button("Open draft")) {
        try {
            openDraft(draftPath_);
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    if (!draft_ || draftEdit_ != editIndex_) {
        ImGui::SameLine();
        ImGui::TextDisabled("(or drop a .wif on the window)");
        return;
    }
    ImGui::SameLine();
    if (ui::Button("Save WIF")) {
        try {
            draft_->save(draftPath_);
            status_ = std::string("saved ") + draftPath_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    // "scale": "draft": the draft's threads per centimetre on this mesh.
    if (ui::Button("Real scale")) {
        try {
            const std::string& target = edits_->edits()[size_t(editIndex_)].target;
            p.repeat = repeatForThreadsPerCm(scene(), edits_->meshesOf(target),
                                             draftThreadsPerCm(draft_->draft(), draft_->name()));
            validate(p);
            status_ = "repeat from the draft's spacing";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    if (ui::Button("Save material with draft")) {
        try {
            const bool gltf = hasExtension(scenePath_, ".gltf") || hasExtension(scenePath_, ".glb");
            const std::string wif = saveMaterialWithDraft(materialPath_, edits_->edits()[size_t(editIndex_)].target, p,
                                                          gltf ? scenePath_ : "", *draft_);
            copyToBuffer(draftPath_, wif);
            status_ = std::string("saved ") + materialPath_ + " and " + wif;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
}

// The draft view of the material the draft belongs to, beside the panel.
void PreviewWindow::drawDraftWindow() {
    if (!draft_ || draftEdit_ < 0 || draftEdit_ >= int(edits_->edits().size())) return;
    WovenParams* woven = &edits_->params(draftEdit_);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Beside the panel, as wide as it leaves the window.
    const ImGuiWindow* panel = ImGui::FindWindowByName("woven");
    const float left = panel ? panel->Rect().Max.x + 8.0f : 456.0f;
    ImGui::SetNextWindowPos(ImVec2(left, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(display.x - left - 8.0f, 200.0f), display.y * 0.45f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Draft");
    try {
        if (draftView_.draw(*draft_, woven->warp_color, woven->weft_color)) {
            *woven = draft_->material(*woven);
            presetIndex_ = -1;
            showFinal_ = false;  // the rendered frame is of the old cloth
            applyEdits();
        }
    } catch (const std::exception& e) {
        status_ = e.what();
    }
    ImGui::End();
}


// What the last click picked, the targets that name it, and "make woven" / "revert".
void PreviewWindow::drawSelection() {
    if (pickedMesh_ < 0 || pickedMesh_ >= int(scene().meshes.size())) {
        ImGui::TextWrapped("Click a surface to select it.");
        return;
    }
    const Mesh& mesh = scene().meshes[size_t(pickedMesh_)];
    std::string path;
    for (const std::string& node : mesh.nodePath) path += (path.empty() ? "" : " > ") + node;
    ImGui::TextWrapped("node %s", path.c_str());
    ImGui::TextWrapped("mesh %s", mesh.meshName.c_str());
    ImGui::TextWrapped("material %s", mesh.material >= 0 ? scene().materials[size_t(mesh.material)].name.c_str() : "(none)");
    const std::vector<std::string> targets = edits_->targetsFor(pickedMesh_);
    targetChoice_ = std::clamp(targetChoice_, 0, int(targets.size()) - 1);
    if (ui::BeginCombo("target", targets[size_t(targetChoice_)].c_str())) {
        for (size_t i = 0; i < targets.size(); ++i)
            if (ui::Selectable(targets[i].c_str(), int(i) == targetChoice_)) targetChoice_ = int(i);
        ui::EndCombo();
    }
    const std::string& target = targets[size_t(targetChoice_)];
    if (ui::Button("Make woven")) {
        try {
            editIndex_ = edits_->makeWoven(target);
            presetIndex_ = -1;
            applyEdits();
            status_ = "made " + target + " woven";
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    ImGui::SameLine();
    if (ui::Button("Revert")) {
        const std::string current = editIndex_ >= 0 ? edits_->edits()[size_t(editIndex_)].target : "";
        if (edits_->revert(target)) {
            editIndex_ = -1;
            for (size_t i = 0; i < edits_->edits().size(); ++i)
                if (edits_->edits()[i].target == current) editIndex_ = int(i);
            applyEdits();
            status_ = "reverted " + target;
        } else {
            status_ = target + " has no edit to revert";
        }
    }
}


}  // namespace woven
