#include "render_section.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "file_fields.h"
#include "frame_io.h"
#include "image_texture.h"
#include "integrators.h"
#include "scene_export.h"
#include "share_page.h"
#include "u3m_export.h"
#include "view_area.h"
#include "widget_map.h"

namespace woven {

void RenderSection::reset(const RenderSettings& settings, const std::string& imagePath, const std::string& exportPath) {
    job_.cancel();
    image_.reset();
    show_ = done_ = false;
    settings_ = settings;
    copyToBuffer(imagePath_, imagePath);
    copyToBuffer(exportPath_, exportPath);
}

void RenderSection::draw(const Shown& shown, const DisplayTransform& display, StatusLine& status) {
    // Two fields, so that Tab moves from the width to the height.
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const float half = std::max((ImGui::CalcItemWidth() - spacing) * 0.5f, 1.0f);
    ImGui::SetNextItemWidth(half);
    ui::InputInt("##width", &settings_.width, 0, 0);
    ImGui::SameLine(0.0f, spacing);
    ImGui::SetNextItemWidth(half);
    ui::InputInt("render size##height", &settings_.height, 0, 0);
    clampSetting(status, "render width", settings_.width, 1, 16384);
    clampSetting(status, "render height", settings_.height, 1, 16384);
    ui::InputInt("spp", &settings_.spp);
    clampSetting(status, "spp", settings_.spp, 1, 1 << 20);
    ui::InputDouble("noise threshold", &settings_.noiseThreshold, 0.01, 0.05, "%.3f");
    clampSetting(status, "noise threshold", settings_.noiseThreshold, 0.0, 1.0);
    if (ui::BeginCombo("integrator", settings_.integrator.c_str())) {
        for (const IntegratorKind& kind : integratorKinds())
            if (ui::Selectable(kind.name, settings_.integrator == kind.name)) settings_.integrator = kind.name;
        ui::EndCombo();
    }
    if (ui::Button("Render")) {
        RenderSettings settings = settings_;
        settings.camera = shown.renderCamera;
        job_.start(shown.scene, settings, shown.denoise);
        image_.reset();
        done_ = false;
        show_ = true;
    }
    if (job_.running()) {
        ImGui::SameLine();
        if (ui::Button("Cancel")) job_.cancel();
    }
    ImGui::SameLine();
    if (ui::Button("Export")) exportShown(shown, status);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ui::InputText("##export file", exportPath_, sizeof exportPath_);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("scene.glb or .gltf: the scene for other renderers; cloth.u3ma or .u3m: the edited cloth for "
                          "fashion tools; page/ (a folder): a web page that shows the cloth (docs/EXPORT.md)");
    if (job_.running() || image_)
        ImGui::ProgressBar(job_.fractionDone(), ImVec2(-1.0f, 0.0f), job_.progressText().c_str());
    if (!job_.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", job_.error().c_str());
    if (!image_) return;
    ui::Checkbox("show the rendered frame", &show_);
    ui::InputText("image file", imagePath_, sizeof imagePath_);
    const bool png = ui::Button("Save PNG");
    ImGui::SameLine();
    const bool exr = ui::Button("Save EXR");
    if (png || exr) {
        std::string path = imagePath_;
        const size_t dot = path.find_last_of('.');
        path = (dot == std::string::npos ? path : path.substr(0, dot)) + (png ? ".png" : ".exr");
        status.attempt([&] {
            writeFrame(path, image_->exr(), display);
            status.say("saved " + path);
        });
    }
}

// The scene as the window shows it, through its camera, woven materials baked; by the path: a
// folder (ending in /) the share page, the edited cloth as a U3M, else the scene as glTF.
void RenderSection::exportShown(const Shown& shown, StatusLine& status) {
    SceneDescription scene = shown.scene;
    scene.camera = shown.viewCamera;
    scene.hasCamera = true;
    status.attempt([&] {
        const std::string path = exportPath_;
        if (!path.empty() && path.back() == '/') {
            const std::vector<std::string> warnings = writeSharePage(scene, path, ShareOptions{});
            for (const std::string& w : warnings) status.warn(path + ": " + w);
            status.say("wrote the page " + path + "index.html");
        } else if (hasExtension(path, ".u3ma") || hasExtension(path, ".u3m")) {
            U3mOptions options;
            options.material = shown.material;
            const U3mExport u3m = exportU3m(scene, path, options);
            for (const std::string& n : u3m.notes) status.warn(path + ": " + n);
            status.say("exported " + u3m.material + " to " + path);
        } else {
            const std::vector<std::string> warnings = exportScene(scene, path, ExportOptions{});
            for (const std::string& w : warnings) status.warn(path + ": " + w);
            status.say("exported " + path + (warnings.empty() ? "" : " (" + std::to_string(warnings.size()) + " warnings: see Messages)"));
        }
    });
}

void RenderSection::poll(const DisplayTransform& display) {
    // The job stores its last snapshot before it stops running: once it was seen stopped, the
    // snapshot taken next is its last.
    const bool stopped = !job_.running();
    if (std::optional<FilmImage> snapshot = job_.newSnapshot()) {
        image_ = std::move(snapshot);
        redisplay(display);
    }
    done_ = stopped && image_ && job_.error().empty();
}

void RenderSection::redisplay(const DisplayTransform& display) {
    if (!image_) return;
    if (texture_ == 0) glGenTextures(1, &texture_);
    uploadImageTexture(texture_, image_->radiance, display);
}

void RenderSection::drawInView() const {
    if (shown()) {
        woven::drawInView(texture_, float(image_->radiance.width) / float(image_->radiance.height));
        return;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    if (settings_.width <= 0 || settings_.height <= 0 || display.y <= 0.0f) return;
    const float width = display.y * float(settings_.width) / float(settings_.height);
    const float x0 = std::max(0.5f * (display.x - width), 0.0f), x1 = std::min(0.5f * (display.x + width), display.x);
    ImGui::GetBackgroundDrawList()->AddRect(ImVec2(x0, 0.0f), ImVec2(x1, display.y), IM_COL32(255, 255, 255, 96), 0.0f, 0, 1.0f);
}

nlohmann::json RenderSection::settingsState() const {
    return {{"width", settings_.width}, {"height", settings_.height}, {"spp", settings_.spp},
            {"noise_threshold", settings_.noiseThreshold}, {"integrator", settings_.integrator}};
}

nlohmann::json RenderSection::frameState() const {
    nlohmann::json image = nullptr, mean = nullptr;
    if (image_) {
        image = {image_->radiance.width, image_->radiance.height};
        const glm::dvec3 m = meanColour(image_->radiance);
        mean = {m.r, m.g, m.b};
    }
    return {{"running", job_.running()}, {"fraction", job_.fractionDone()}, {"progress", job_.progressText()},
            {"error", job_.error()}, {"image", image}, {"mean", mean}, {"shown", shown()}, {"done", done_}};
}

void RenderSection::releaseTexture() {
    if (texture_ != 0) glDeleteTextures(1, &texture_);
    texture_ = 0;
}

}  // namespace woven
