// The panel's Selection and Material sections (the sliders generated from wovenParamTable(),
// presets, saving and loading, the draft's file), and the Draft window beside the panel.
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <string>

#include "draft_material.h"
#include "material_file.h"
#include "preview_window_impl.h"
#include "uv_scale.h"
#include "weave_candidates.h"
#include "weave_draft.h"
#include "weave_presets.h"
#include "woven_params.h"

namespace woven {

// The Fabrics menu: a fabric chosen there becomes the edited material, its draft (or its weave
// as one) in the draft view.
void PreviewWindow::drawFabricControls(WovenParams& p) {
    const std::string target = editedTarget();
    if (const std::string name = fabrics_.drawMenu(target); !name.empty()) {
        status_.attempt([&] {
            std::vector<std::string> warnings;
            ChosenFabric chosen = chooseFabric(target, name, scene(), edits_->meshesOf(target), warnings);
            p = chosen.params;
            materialEdited();
            showDraftOf(chosen.wif, warnings);
            if (chosen.wif.empty()) showWeaveAsDraft(p, name, true);
            fabrics_.setChosen(std::move(chosen));
            status_.say("fabric " + name + (warnings.empty() ? "" : " (" + warnings.front() + ")"));
            for (const std::string& w : warnings) status_.warn(w);
        });
    }
    fabrics_.drawMeasures(target, p, scene(), edits_->meshesOf(target));
}

const std::optional<glm::dvec2>& PreviewWindow::metresPerUvOf(const std::string& target) {
    return fabrics_.metresPerUv(target, scene(), edits_->meshesOf(target));
}

void PreviewWindow::showDraftOf(const std::string& wif, std::vector<std::string>& warnings) {
    if (wif.empty()) {
        draft_.closeFor(editIndex_);
        return;
    }
    draft_.open(DraftEditor::open(wif, warnings), editIndex_, true, wif);
}

void PreviewWindow::showWeaveAsDraft(const WovenParams& p, const std::string& name, bool show) {
    std::string file = name;  // a material's name may hold what a file name cannot
    for (char& c : file)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    const std::string path = besideScene(scenePath_, "-" + file + ".wif", file + ".wif");
    draft_.open(DraftEditor(weaveDraft(p, name), path), editIndex_, show, path);
}

namespace {

// A drag moves a logarithmic parameter by a decade in this many pixels, whatever its range (a
// slider 240 pixels wide spans e_x's eight decades in 30 pixels a decade).
constexpr float kPixelsPerDecade = 150.0f;
// The smallest magnitude a logarithmic drag of "%.4g" reaches above 0 (ImGui's epsilon for it).
constexpr float kLogZero = 1e-4f;

float logDragSpeed(const ParamInfo& info) {
    const float decades = std::log10(info.max / std::max(info.min, kLogZero));
    return (info.max - info.min) / (decades * kPixelsPerDecade);
}

// Whether any yarn type sets `field` to something other than 0.
bool anyYarnSets(const WovenParams& p, YarnField field) {
    return std::any_of(p.yarns.begin(), p.yarns.end(), [&](const YarnSpec& y) { return y.set[field] && y.value[field] != 0.0f; });
}

// Why a parameter changes nothing on this material (drawn disabled, the reason its tooltip), or
// nothing: it acts.
std::string inactiveBecause(const ParamInfo& info, const WovenParams& p) {
    const std::string name = info.name;
    for (const auto& [side, colours] : {std::pair{"weft_color", &p.weft_colors}, std::pair{"warp_color", &p.warp_colors}})
        if (name == side && !colours->empty())
            return "every thread of this side has its own colour: edit them in \"thread colours\" below (" +
                   std::to_string(colours->size()) + " threads)";
    if (name == "transmission_gloss" && p.transmission == 0.0f && !anyYarnSets(p, kYarnTransmission))
        return "yarn transmission is 0: no light passes through the yarns to take this gloss";
    if (name == "noise_scale" && p.noise == 0.0f && !anyYarnSets(p, kYarnNoise)) return "noise is 0: there is no noise to scale";
    if (name == "backing" || name == "backing_color") {
        if (name == "backing_color" && p.backing == 0)
            return "gaps are see-through (backing 0): set \"gaps show backing\" to 1 to see this colour";
        const bool narrowYarns = p.yarn_width < 1.0f || p.warp_width < 1.0f ||
                                 std::any_of(p.yarns.begin(), p.yarns.end(),
                                             [](const YarnSpec& y) { return y.set[kYarnWidth] && y.value[kYarnWidth] < 1.0f; });
        if (!narrowYarns) return "the yarns fill their cells (widths 1): there are no gaps";
    }
    return "";
}

// Every colour the threads have, in order of first use (ends, then picks): a side without
// per-thread colours has its own colour.
std::vector<glm::vec3> threadPalette(const WovenParams& p) {
    std::vector<glm::vec3> palette;
    auto add = [&](const glm::vec3& c) {
        if (std::find(palette.begin(), palette.end(), c) == palette.end()) palette.push_back(c);
    };
    for (const glm::vec3& c : p.warp_colors) add(c);
    if (p.warp_colors.empty()) add(p.warp_color);
    for (const glm::vec3& c : p.weft_colors) add(c);
    if (p.weft_colors.empty()) add(p.weft_color);
    return palette;
}

// Every thread of colour `from` takes colour `to`.
void recolour(WovenParams& p, const glm::vec3& from, const glm::vec3& to) {
    for (std::vector<glm::vec3>* list : {&p.warp_colors, &p.weft_colors})
        std::replace(list->begin(), list->end(), from, to);
    if (p.warp_colors.empty() && p.warp_color == from) p.warp_color = to;
    if (p.weft_colors.empty() && p.weft_color == from) p.weft_color = to;
}

}  // namespace

// The weave: a preset, or the (i, j, k) of MODEL.md. Either replaces a tile, a draft's too: its
// threads keep their colours, yarns and spacing by position, and the draft view closes, for the
// draft no longer describes the cloth.
void PreviewWindow::drawWeaveControls(WovenParams& p) {
    const auto& presets = weavePresets();
    const int current = presetOf(p);
    // A tile (a draft's, or drawn) of the regular family shows as its (i, j, k): the default
    // denim's draft is a 3/1 twill, not the pattern's (1, 1, 1) the tile overrides.
    const std::optional<glm::ivec3> regular = p.tile.empty() ? std::nullopt : regularWeaveOf(p.tile);
    const std::string name = current >= 0   ? presets[size_t(current)].name
                             : regular      ? "(a tile: " + describeWeave(*regular) + ")"
                             : p.tile.empty() ? "(custom)"
                                              : "(a tile)";
    std::string chosen;
    if (ui::BeginCombo("weave preset", name.c_str())) {
        for (size_t i = 0; i < presets.size(); ++i)
            if (ui::Selectable(presets[i].name.c_str(), int(i) == current)) {
                applyPreset(presets[i], p);
                chosen = presets[i].name;
            }
        ui::EndCombo();
    }
    const ParamInfo& pattern = *std::find_if(wovenParamTable().begin(), wovenParamTable().end(),
                                             [](const ParamInfo& info) { return info.type == ParamType::IVec3; });
    glm::ivec3 shown = regular.value_or(p.pattern);
    int* v = &shown.x;
    if (ui::InputInt3(pattern.label, v)) {
        for (int c = 0; c < 3; ++c) v[c] = std::clamp(v[c], int(pattern.min), int(pattern.max));
        p.pattern = shown;
        p.tile.clear();
        chosen = "(" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + ")";
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s: %s%s", pattern.name, pattern.description,
                          p.tile.empty() ? "" : "\nthe weave is a tile now (a draft's or drawn): a weave typed here replaces it");
    if (!chosen.empty() && draft_.openFor(editIndex_)) {
        draft_.closeFor(editIndex_);
        status_.say("the weave " + chosen + " replaces the draft's; its threads keep their colours");
    }
}

// A swatch for each colour the threads have: editing one recolours every thread of that colour.
void PreviewWindow::drawThreadPalette(WovenParams& p) {
    if (p.warp_colors.empty() && p.weft_colors.empty()) return;
    ImGui::TextUnformatted("thread colours");
    const std::vector<glm::vec3> palette = threadPalette(p);
    for (size_t i = 0; i < palette.size(); ++i) {
        glm::vec3 c = palette[i];
        const std::string label = "thread colour " + std::to_string(i + 1);
        if (ui::ColorEdit3(label.c_str(), &c.x, ImGuiColorEditFlags_Float)) recolour(p, palette[i], c);
        if (ImGui::IsItemHovered()) {
            const auto count = [&](const std::vector<glm::vec3>& list) { return std::count(list.begin(), list.end(), palette[i]); };
            ImGui::SetTooltip("%td of %zu ends, %td of %zu picks: a click edits every thread of this colour",
                              count(p.warp_colors), p.warp_colors.size(), count(p.weft_colors), p.weft_colors.size());
        }
    }
}

// The thread spacing as a weaver gives it, ends and picks per centimetre, where the meshes' size
// is known (else false: the repeat per UV unit is all there is to set).
bool PreviewWindow::drawThreadsPerCm(WovenParams& p, const ParamInfo& repeat) {
    const std::optional<glm::dvec2>& scale = metresPerUvOf(edits_->edits()[size_t(editIndex_)].target);
    if (!scale) return false;
    const glm::vec2 cmPerUv = glm::vec2(100.0 * *scale);
    glm::vec2 perCm = p.repeat / cmPerUv;
    ParamInfo range = repeat;
    range.min = repeat.min / std::max(cmPerUv.x, cmPerUv.y);
    range.max = repeat.max / std::min(cmPerUv.x, cmPerUv.y);
    if (ui::DragFloat2("ends, picks per cm", &perCm.x, logDragSpeed(range), range.min, range.max, "%.4g",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        p.repeat = glm::clamp(perCm * cmPerUv, repeat.min, repeat.max);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("repeat: warp ends and weft picks per centimetre on these meshes (%.4g x %.4g cm per UV unit)\n"
                          "(Ctrl+click to type a value)", cmPerUv.x, cmPerUv.y);
    return true;
}

void PreviewWindow::drawMaterialControls(WovenParams& p) {
    drawFabricControls(p);
    drawWeaveControls(p);
    for (const ParamInfo& info : wovenParamTable()) {
        // The tile and the per-thread lists: the weave above, the palette and the draft view below.
        if (!isNumeric(info.type) || info.type == ParamType::IVec3) continue;
        char* field = reinterpret_cast<char*>(&p) + info.offset;
        ImGui::PushID(info.name);
        const ImGuiSliderFlags flags = info.logScale ? ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp
                                                     : ImGuiSliderFlags_AlwaysClamp;
        const std::string inactive = inactiveBecause(info, p);
        ImGui::BeginDisabled(!inactive.empty());
        switch (info.type) {
        case ParamType::Float:
            if (info.logScale)
                ui::DragFloat(info.label, reinterpret_cast<float*>(field), logDragSpeed(info), info.min, info.max, "%.4g",
                              flags);
            else
                ui::SliderFloat(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Int:
            // A switch (0 or 1) is a checkbox: a slider of two values moves only past its middle.
            if (info.min == 0 && info.max == 1) {
                bool on = *reinterpret_cast<int*>(field) != 0;
                if (ui::Checkbox(info.label, &on)) *reinterpret_cast<int*>(field) = on;
            } else {
                ui::SliderInt(info.label, reinterpret_cast<int*>(field), int(info.min), int(info.max));
            }
            break;
        case ParamType::Vec2:
            if (info.name == std::string("repeat") && drawThreadsPerCm(p, info)) break;
            ui::SliderFloat2(info.label, reinterpret_cast<float*>(field), info.min, info.max, "%.4g", flags);
            break;
        case ParamType::Vec3:
            ui::ColorEdit3(info.label, reinterpret_cast<float*>(field), ImGuiColorEditFlags_Float);
            break;
        default: break;
        }
        ImGui::EndDisabled();
        // The scene-file key and its meaning, so what the panel tunes can be written by hand.
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            if (!inactive.empty()) ImGui::SetTooltip("%s: %s", info.name, inactive.c_str());
            else ImGui::SetTooltip("%s: %s\n(Ctrl+click to type a value)", info.name, info.description);
        }
        ImGui::PopID();
    }
    drawThreadPalette(p);
    try {
        validate(p);
    } catch (const std::exception& e) {
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", e.what());
    }

    ui::InputText("scene file", materialPath_, sizeof materialPath_);
    const std::string& target = edits_->edits()[size_t(editIndex_)].target;
    if (ui::Button("Save")) status_.attempt([&] { saveSceneFile(savePath_, false); });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Ctrl+S: every woven material, the view and the render settings into %s, which woven render "
                          "renders as the Render button does", savePath_.c_str());
    ImGui::SameLine();
    if (ui::Button("Save As")) status_.attempt([&] { saveSceneFile(materialPath_, true); });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("the same into a new woven scene file (.json) named by \"scene file\"; Save then writes there");
    ImGui::SameLine();
    if (ui::Button("Load material")) {
        status_.attempt([&] {
            std::vector<std::string> warnings;
            const MaterialJson read = loadMaterial(materialPath_, target, p, warnings);
            p = scaledToMeshes(read, scene(), edits_->meshesOf(target), warnings);
            if (fabrics_.chosenFor(target)) fabrics_.setChosen(std::nullopt);
            materialEdited();
            status_.say(std::string("loaded ") + materialPath_);
            if (!read.wif.empty()) showDraftOf(read.wif, warnings);
            for (const std::string& w : warnings) status_.warn(w);
        });
    }
    drawDraftControls(p);
}

void PreviewWindow::drawDraftControls(WovenParams& p) {
    ImGui::Separator();
    ui::InputText("draft file", draft_.path(), DraftSection::kPathSize);
    if (ui::Button("Open draft")) {
        status_.attempt([&] {
            openDraft(draft_.path());
        });
    }
    DraftEditor* editor = draft_.of(editIndex_);
    if (!editor) {
        ImGui::SameLine();
        if (ui::Button("Draft view")) status_.attempt([&] { showWeaveAsDraft(p, "weave", true); });
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("this weave and its thread colours as a draft, to edit thread by thread and save as WIF "
                              "(or drop a .wif on the window)");
        return;
    }
    ImGui::SameLine();
    if (ui::Button("Save WIF")) {
        status_.attempt([&] {
            editor->save(draft_.path());
            status_.say(std::string("saved ") + draft_.path());
        });
    }
    ImGui::SameLine();
    // "scale": "draft": the draft's threads per centimetre on this mesh.
    if (ui::Button("Real scale")) {
        status_.attempt([&] {
            const std::string& target = edits_->edits()[size_t(editIndex_)].target;
            p.repeat = repeatForThreadsPerCm(scene(), edits_->meshesOf(target),
                                             draftThreadsPerCm(editor->draft(), editor->name()));
            validate(p);
            materialEdited();
            status_.say("repeat from the draft's spacing");
        });
    }
    if (ui::Button("Save material with draft")) {
        status_.attempt([&] {
            const bool gltf = hasExtension(scenePath_, ".gltf") || hasExtension(scenePath_, ".glb");
            const std::string wif = saveMaterialWithDraft(materialPath_, edits_->edits()[size_t(editIndex_)].target, p,
                                                          gltf ? scenePath_ : "", *editor);
            draft_.setPath(wif);
            status_.say(std::string("saved ") + materialPath_ + " and " + wif);
        });
    }
}

// The draft view of the material the draft belongs to, beside the panel.
void PreviewWindow::drawDraftWindow() {
    const int edit = draft_.edit();
    if (edit < 0 || edit >= int(edits_->edits().size())) return;
    if (draft_.drawWindow(edits_->params(edit), status_)) {
        materialEdited();
        status_.attempt([&] { applyEdits(); });
    }
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
        status_.attempt([&] {
            editIndex_ = edits_->makeWoven(target);
            materialEdited();
            applyEdits();
            status_.say("made " + target + " woven");
        });
    }
    ImGui::SameLine();
    if (ui::Button("Revert")) {
        const std::string current = editIndex_ >= 0 ? edits_->edits()[size_t(editIndex_)].target : "";
        if (edits_->revert(target)) {
            editIndex_ = -1;
            for (size_t i = 0; i < edits_->edits().size(); ++i)
                if (edits_->edits()[i].target == current) editIndex_ = int(i);
            materialEdited();
            applyEdits();
            status_.say("reverted " + target);
        } else {
            status_.say(target + " has no edit to revert");
        }
    }
}


}  // namespace woven
