#pragma once
// The panel's Fit section: `woven fit` (docs/FIT.md) from the window. The shots' photographs are
// fitted on a background thread (fit_job.h) while the section shows the stage and the loss
// falling; the fitted material then becomes the edit it was started for, at the shots' thread
// counts on its own meshes, ready for the sliders.
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>

#include "fit_job.h"
#include "status_line.h"
#include "woven_edits.h"

namespace woven {

class FitSection {
public:
    // The length per UV unit of a target's meshes (nullopt: they have no UVs to measure).
    using MetresPerUv = std::function<const std::optional<glm::dvec2>&(const std::string&)>;

    // `editedTarget`: the edit the panel tunes, which Fit fits (empty: none).
    void draw(const std::string& editedTarget, StatusLine& status);
    // A finished fit's material into the edit it was started for, if `edits` still has it, with
    // the shots' threads per cm laid on its meshes where both are measured. Returns that edit's
    // index, or -1 (nothing finished, or the edit is gone: the status line says so).
    int applyFinished(WovenEdits& edits, const MetresPerUv& metresPerUv, StatusLine& status);

    bool running() const { return job_.running(); }
    // For the widget map: the job's stage, renders, error, and whether the last fit was applied.
    nlohmann::json state() const;

private:
    FitJob job_;
    std::string target_;    // the edit being fitted, until its fit is applied
    bool applied_ = false;  // the last fit was
    char shots_[1024] = "";
    char swatch_[256] = "";
    double seconds_ = 180.0;
};

}  // namespace woven
