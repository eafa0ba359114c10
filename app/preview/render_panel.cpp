// The panel's Render section: the final frame's settings, the Render button (core's RenderJob for
// the window's camera, on a background thread), Export, the progress, and saving the frame.
#include <imgui.h>

#include <algorithm>
#include <iostream>
#include <string>

#include "frame_io.h"
#include "image_io.h"
#include "integrators.h"
#include "preview_window_impl.h"
#include "scene_export.h"
#include "share_page.h"
#include "u3m_export.h"

namespace woven {

void PreviewWindow::drawRenderControls() {
    // Two fields, so that Tab moves from the width to the height.
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const float half = std::max((ImGui::CalcItemWidth() - spacing) * 0.5f, 1.0f);
    ImGui::SetNextItemWidth(half);
    ui::InputInt("##width", &render_.width, 0, 0);
    ImGui::SameLine(0.0f, spacing);
    ImGui::SetNextItemWidth(half);
    ui::InputInt("render size##height", &render_.height, 0, 0);
    clampSetting(status_, "render width", render_.width, 1, 16384);
    clampSetting(status_, "render height", render_.height, 1, 16384);
    ui::InputInt("spp", &render_.spp);
    clampSetting(status_, "spp", render_.spp, 1, 1 << 20);
    ui::InputDouble("noise threshold", &render_.noiseThreshold, 0.01, 0.05, "%.3f");
    clampSetting(status_, "noise threshold", render_.noiseThreshold, 0.0, 1.0);
    if (ui::BeginCombo("integrator", render_.integrator.c_str())) {
        for (const IntegratorKind& kind : integratorKinds())
            if (ui::Selectable(kind.name, render_.integrator == kind.name)) render_.integrator = kind.name;
        ui::EndCombo();
    }
    if (ui::Button("Render")) {
        RenderSettings settings = render_;
        settings.camera = renderCamera();
        final_.start(scene(), settings, options_.frame.denoise);
        finalImage_.reset();
        finalDone_ = false;
        showFinal_ = true;
    }
    if (final_.running()) {
        ImGui::SameLine();
        if (ui::Button("Cancel")) final_.cancel();
    }
    // Export: the scene as the window shows it, through its camera, woven materials baked.
    ImGui::SameLine();
    if (ui::Button("Export")) {
        SceneDescription shown = scene();
        shown.camera = camera_.camera();
        shown.hasCamera = true;
        status_.attempt([&] {
            // By the path: a folder (ending in /) the share page, the edited cloth as a U3M, else
            // the scene as glTF.
            const std::string path = exportPath_;
            if (!path.empty() && path.back() == '/') {
                const std::vector<std::string> warnings = writeSharePage(shown, path, ShareOptions{});
                for (const std::string& w : warnings) status_.warn(path + ": " + w);
                status_.say("wrote the page " + path + "index.html");
            } else if (hasExtension(path, ".u3ma") || hasExtension(path, ".u3m")) {
                U3mOptions options;
                if (editIndex_ >= 0) {
                    const int m = edits_->materialOf(edits_->edits()[size_t(editIndex_)].target);
                    if (m >= 0) options.material = shown.materials[size_t(m)].name;
                }
                const U3mExport u3m = exportU3m(shown, path, options);
                for (const std::string& n : u3m.notes) status_.warn(path + ": " + n);
                status_.say("exported " + u3m.material + " to " + path);
            } else {
                const std::vector<std::string> warnings = exportScene(shown, path, ExportOptions{});
                for (const std::string& w : warnings) status_.warn(path + ": " + w);
                status_.say("exported " + path + (warnings.empty() ? "" : " (" + std::to_string(warnings.size()) + " warnings: see Messages)"));
            }
        });
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ui::InputText("##export file", exportPath_, sizeof exportPath_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("scene.glb or .gltf: the scene for other renderers; cloth.u3ma or .u3m: the edited cloth for "
                          "fashion tools; page/ (a folder): a web page that shows the cloth (docs/EXPORT.md)");
    if (final_.running() || finalImage_)
        ImGui::ProgressBar(final_.fractionDone(), ImVec2(-1.0f, 0.0f), final_.progressText().c_str());
    if (!final_.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", final_.error().c_str());
    if (!finalImage_) return;
    ui::Checkbox("show the rendered frame", &showFinal_);
    ui::InputText("image file", imagePath_, sizeof imagePath_);
    const bool png = ui::Button("Save PNG");
    ImGui::SameLine();
    const bool exr = ui::Button("Save EXR");
    if (png || exr) {
        std::string path = imagePath_;
        const size_t dot = path.find_last_of('.');
        path = (dot == std::string::npos ? path : path.substr(0, dot)) + (png ? ".png" : ".exr");
        status_.attempt([&] {
            writeFrame(path, finalImage_->exr(), display_);
            status_.say("saved " + path);
        });
    }
}

}  // namespace woven
