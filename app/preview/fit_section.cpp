#include "fit_section.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "weave_candidates.h"
#include "widget_map.h"

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

void FitSection::draw(const std::string& editedTarget, StatusLine& status) {
    ImGui::TextWrapped("Fits the edited woven material to photographs of a swatch: shot files are scene files with a "
                       "\"photo\" key, separated by spaces (docs/FIT.md).");
    ui::InputText("shot files", shots_, sizeof shots_);
    ui::InputText("swatch", swatch_, sizeof swatch_);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the swatch in the shots: a material, mesh:NAME or node:NAME (empty: the edited one's)");
    ui::InputDouble("fit seconds", &seconds_, 10.0, 60.0, "%.0f");
    clampSetting(status, "fit seconds", seconds_, 1.0, 3600.0);
    if (!job_.running() && ui::Button("Fit")) {
        if (editedTarget.empty()) {
            status.say("fit: nothing is woven to fit: click a surface and make it woven");
        } else {
            target_ = editedTarget;
            const std::string swatch = swatch_[0] ? std::string(swatch_) : target_;
            job_.start(splitPaths(shots_), swatch, seconds_);
            applied_ = false;
            status.say("fitting " + target_ + " to " + shots_);
        }
    }
    if (job_.running()) {
        if (ui::Button("Cancel fit")) job_.cancel();  // keeps the best fit so far
        const FitProgress p = job_.progress();
        char text[160];
        std::snprintf(text, sizeof text, "%s, %d renders, loss %.4g", p.stage.c_str(), p.evaluations, p.bestLoss);
        ImGui::ProgressBar(p.budget > 0.0 ? float(std::min(1.0, p.elapsed / p.budget)) : 0.0f, ImVec2(-1.0f, 0.0f), text);
    }
    drawLossPlot(job_.lossHistory());
    if (!job_.error().empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", job_.error().c_str());
}

int FitSection::applyFinished(WovenEdits& edits, const MetresPerUv& metresPerUv, StatusLine& status) {
    if (job_.running()) return -1;
    if (const std::string error = job_.error(); !error.empty() && !target_.empty()) {
        status.say("fit: " + error);
        target_.clear();
    }
    std::optional<FittedFabric> fitted = job_.takeResult();
    if (!fitted) return -1;
    const auto& list = edits.edits();
    const auto edit = std::find_if(list.begin(), list.end(), [&](const auto& e) { return e.target == target_; });
    if (edit == list.end()) {
        status.say("fit: " + target_ + " is no longer woven in this scene: the fit was not applied");
        return -1;
    }
    WovenParams params = fitted->fit.params;
    const std::optional<glm::dvec2>& scale = metresPerUv(target_);
    std::string counts;
    if (scale && fitted->threadsPerCm) {
        params.repeat = glm::vec2(*fitted->threadsPerCm * 100.0 * *scale);
        std::ostringstream s;
        s.precision(3);
        s << ", " << fitted->threadsPerCm->x << " x " << fitted->threadsPerCm->y << " threads/cm";
        counts = s.str();
    }
    const int index = int(edit - list.begin());
    edits.params(index) = params;
    applied_ = true;
    std::ostringstream s;
    s.precision(4);
    s << "fit: " << describeWeave(params.pattern) << counts << ", loss " << fitted->fit.loss << ", "
      << fitted->fit.evaluations << " renders" << (fitted->fit.complete ? "" : " (the best so far)") << ", applied to "
      << target_;
    status.say(s.str());
    for (const std::string& w : fitted->fit.warnings) status.warn("fit: " + w);
    target_.clear();
    return index;
}

nlohmann::json FitSection::state() const {
    const FitProgress p = job_.progress();
    return {{"running", job_.running()}, {"stage", p.stage}, {"evaluations", p.evaluations},
            {"error", job_.error()}, {"applied", applied_}, {"loss_points", job_.lossHistory().size()}};
}

}  // namespace woven
