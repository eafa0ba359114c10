// The panel's Fit section: `woven fit` (docs/FIT.md) from the window. The shots' photographs are
// fitted on a background thread while the window shows the stage and the loss falling; the
// fitted material then becomes the edited one, at the shots' thread counts on its own meshes,
// ready for the sliders.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "preview_window_impl.h"
#include "uv_scale.h"
#include "weave_candidates.h"

namespace woven {

namespace {

std::vector<std::string> splitPaths(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> paths;
    for (std::string path; in >> path;) paths.push_back(path);
    return paths;
}

// The best loss after each render, on a log scale: the first renders' loss is orders of magnitude
// above the last ones', which a linear plot flattens onto its floor.
void drawLossPlot(const std::vector<float>& history) {
    if (history.empty()) return;
    std::vector<float> logLoss;
    for (float loss : history) logLoss.push_back(std::log10(loss));
    if (logLoss.size() == 1) logLoss.push_back(logLoss.front());  // a line needs two points
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "best loss %.4g (log scale)", std::pow(10.0, double(logLoss.back())));
    ImGui::PlotLines("##loss", logLoss.data(), int(logLoss.size()), 0, overlay, FLT_MAX, FLT_MAX, ImVec2(-1.0f, 60.0f));
}

}  // namespace

void PreviewWindow::drawFitControls() {
    ImGui::TextWrapped("Fits the edited woven material to photographs of a swatch: shot files are scene files with a "
                       "\"photo\" key, separated by spaces (docs/FIT.md).");
    ui::InputText("shot files", fitShots_, sizeof fitShots_);
    ui::InputText("swatch", fitSwatch_, sizeof fitSwatch_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the swatch in the shots: a material, mesh:NAME or node:NAME (empty: the edited one's)");
    ui::InputDouble("fit seconds", &fitSeconds_, 10.0, 60.0, "%.0f");
    clampSetting("fit seconds", fitSeconds_, 1.0, 3600.0);
    if (!fit_.running() && ui::Button("Fit")) {
        if (!editedParams()) {
            status_ = "fit: nothing is woven to fit: click a surface and make it woven";
        } else {
            fitTarget_ = edits_->edits()[size_t(editIndex_)].target;
            const std::string swatch = fitSwatch_[0] ? std::string(fitSwatch_) : fitTarget_;
            fit_.start(splitPaths(fitShots_), swatch, fitSeconds_);
            fitApplied_ = false;
            status_ = "fitting " + fitTarget_ + " to " + fitShots_;
        }
    }
    if (fit_.running()) {
        if (ui::Button("Cancel fit")) fit_.cancel();  // keeps the best fit so far
        const FitProgress p = fit_.progress();
        char text[160];
        std::snprintf(text, sizeof text, "%s, %d renders, loss %.4g", p.stage.c_str(), p.evaluations, p.bestLoss);
        ImGui::ProgressBar(p.budget > 0.0 ? float(std::min(1.0, p.elapsed / p.budget)) : 0.0f, ImVec2(-1.0f, 0.0f), text);
    }
    drawLossPlot(fit_.lossHistory());
    if (!fit_.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", fit_.error().c_str());
}

// The finished fit's material into the edit it was started for (if it is still there), with the
// shots' threads per cm laid on the edit's own meshes where both are measured.
void PreviewWindow::applyFinishedFit() {
    if (fit_.running()) return;
    if (const std::string error = fit_.error(); !error.empty() && !fitTarget_.empty()) {
        status_ = "fit: " + error;
        fitTarget_.clear();
    }
    std::optional<FittedFabric> fitted = fit_.takeResult();
    if (!fitted) return;
    const auto& edits = edits_->edits();
    const auto edit = std::find_if(edits.begin(), edits.end(), [&](const auto& e) { return e.target == fitTarget_; });
    if (edit == edits.end()) {
        status_ = "fit: " + fitTarget_ + " is no longer woven in this scene: the fit was not applied";
        return;
    }
    WovenParams params = fitted->fit.params;
    const std::optional<glm::dvec2>& scale = metresPerUvOf(fitTarget_);
    std::string counts;
    if (scale && fitted->threadsPerCm) {
        params.repeat = glm::vec2(*fitted->threadsPerCm * 100.0 * *scale);
        std::ostringstream s;
        s.precision(3);
        s << ", " << fitted->threadsPerCm->x << " x " << fitted->threadsPerCm->y << " threads/cm";
        counts = s.str();
    }
    editIndex_ = int(edit - edits.begin());
    edits_->params(editIndex_) = params;
    chosenFabric_.reset();
    materialEdited();
    applyEdits();
    fitApplied_ = true;
    std::ostringstream s;
    s.precision(4);
    s << "fit: " << describeWeave(params.pattern) << counts << ", loss " << fitted->fit.loss << ", "
      << fitted->fit.evaluations << " renders" << (fitted->fit.complete ? "" : " (the best so far)") << ", applied to "
      << fitTarget_;
    status_ = s.str();
    for (const std::string& w : fitted->fit.warnings) warn("fit: " + w);
    fitTarget_.clear();
}

const std::optional<glm::dvec2>& PreviewWindow::metresPerUvOf(const std::string& target) {
    auto [scale, first] = metresPerUv_.try_emplace(target);
    if (first) {
        try {
            scale->second = worldLengthPerUv(scene(), edits_->meshesOf(target));
        } catch (const std::invalid_argument&) {  // no UVs: a cloth of no known size
        }
    }
    return scale->second;
}

}  // namespace woven
