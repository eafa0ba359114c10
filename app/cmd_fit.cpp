// `woven fit SHOT.json ... --target NAME -o FABRIC.json`: the woven material whose renders of the
// shots have their photographs' statistics (docs/FIT.md).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "exposure_fold.h"
#include "fabric_fit.h"
#include "fit_output.h"
#include "fit_report.h"
#include "interrupt_guard.h"
#include "number_checks.h"
#include "threads_option.h"
#include "output_path.h"
#include "progress_bar.h"
#include "weave_candidates.h"

namespace woven {

namespace {

struct FitCommand {
    std::vector<std::string> shots;
    std::string target, out, report;
    double time = 180.0;
    uint64_t seed = 1;
    int spp = 4;
    int threads = 0;
};

void writeJson(const std::string& path, const nlohmann::json& j) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << j.dump(2) << "\n";
        if (!f) throw std::runtime_error(path + ": cannot be written");
    });
}

int runFit(const FitCommand& o) {
    const auto start = std::chrono::steady_clock::now();  // --time counts from here
    std::vector<Shot> shots;
    for (const std::string& path : o.shots) {
        shots.push_back(loadShot(path, o.target));
    }
    // Every output is checked before the fit: the inputs read are none of them (output_path.h).
    checkOutput(o.out);
    checkOutput(partialName(o.out));
    if (!o.report.empty()) checkFitReport(o.report, shots.size());

    FitOptions options;
    options.seconds = o.time - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    options.render.seed = o.seed;
    options.render.spp = o.spp;
    options.render.threads = o.threads;
    FitResult result;
    {
        InterruptGuard guard;
        ProgressBar bar("fit");
        result = fitFabric(shots, options, interrupted(), [&](const FitProgress& p) {
            std::ostringstream s;
            s << p.stage << "  " << p.evaluations << " renders  best loss " << std::setprecision(4) << p.bestLoss
              << "  elapsed " << formatDuration(p.elapsed) << " of " << formatDuration(p.budget);
            bar.update(std::min(1.0, p.elapsed / p.budget), s.str());
        });
        bar.finish();
    }
    const bool wasInterrupted = interrupted().load();
    for (const std::string& w : result.warnings) std::cerr << "warning: fit: " << w << "\n";
    if (!result.complete && !wasInterrupted)
        std::cerr << "warning: fit: --time " << o.time << " s ran out before the fit finished its stages; "
                  << o.out << " holds the best fit so far (docs/FIT.md says how long a fit takes)\n";
    const bool anyBacklit = std::any_of(shots.begin(), shots.end(), [](const Shot& s) { return s.backlit; });
    const ExposureFold fold = foldFittedExposure(shots, result);
    std::vector<std::string> notes;
    if (!fold.note.empty()) notes.push_back(fold.note);
    if (!anyBacklit) {
        std::ostringstream s;
        s << "transmission " << fold.params.transmission << " and transmission_gloss " << fold.params.transmission_gloss
          << " are not fitted: no shot is lit from behind, so they keep the shots' material's values";
        notes.push_back(s.str());
    }
    nlohmann::json material = fittedMaterialJson(fold.params, shots[0]);
    std::string comment;
    for (const std::string& note : notes) {
        std::cerr << "fit: " << note << "\n";
        comment += (comment.empty() ? "woven fit: " : "; ") + note;
    }
    if (!comment.empty()) material["comment"] = comment;
    // An interrupted fit is unfinished: it never takes the final name (as render's .partial.exr).
    const std::string out = wasInterrupted ? partialName(o.out) : o.out;
    writeJson(out, material);
    std::cerr << (wasInterrupted ? "interrupted: wrote the best fit so far to " : "wrote ") << out << "\n";

    std::cout << "weave " << describeWeave(result.params.pattern);
    if (const auto counts = threadsPerCm(shots[0], result.params.repeat))
        std::cout << ", " << std::setprecision(4) << counts->x << " ends x " << counts->y << " picks per cm";
    else
        std::cout << ", repeat " << result.params.repeat.x << " x " << result.params.repeat.y << " per UV unit";
    std::cout << ", loss " << std::setprecision(4) << result.loss << ", " << result.evaluations << " renders";
    if (!result.history.empty()) std::cout << " in " << std::setprecision(3) << result.history.back().first << " s";
    if (result.exposure != 1.0)
        std::cout << ", exposure " << std::setprecision(4) << result.exposure << (fold.folded ? " (folded into the colours)" : "");
    if (anyBacklit)
        std::cout << ", transmission " << std::setprecision(3) << fold.params.transmission << " (gloss "
                  << fold.params.transmission_gloss << ") from the backlit shots";
    else
        std::cout << ", transmission not fitted";
    std::cout << "\n";
    if (!o.report.empty()) {
        for (const std::string& w : writeFitReport(o.report, shots, result)) std::cerr << "warning: fit: " << w << "\n";
        std::cerr << "wrote the report to " << o.report << "\n";
    }
    return wasInterrupted ? 130 : 0;
}

}  // namespace

void addFitCommand(CLI::App& app) {
    auto o = std::make_shared<FitCommand>();
    CLI::App* cmd = app.add_subcommand(
        "fit", "Fit a woven material to photographs of a swatch: each SHOT is a scene file with a \"photo\" key (docs/FIT.md)");
    cmd->add_option("shots", o->shots, "shot files (woven scene files with \"photo\")")->required();
    cmd->add_option("--target", o->target, "the part of each shot that is the swatch: a material, mesh:NAME, node:NAME or a glob")
        ->required();
    cmd->add_option("-o,--out", o->out, "the fitted material, JSON for a scene file's \"materials\"")->required();
    cmd->add_option("--time", o->time, "time budget in seconds (default 180); the best fit so far when it runs out")
        ->check(positiveNumber());
    cmd->add_option("--report", o->report, "folder for the photos beside their fitted renders, each statistic's error "
                                           "and the loss against time");
    cmd->add_option("--seed", o->seed, "seed of the fit's renders (default 1): the loss is a pure function of the parameters")
        ->transform(wholeNumber(0));
    cmd->add_option("--spp", o->spp, "samples per pixel of the fit's renders (default 4)")->transform(wholeNumber(1, 1024));
    addThreadsOption(*cmd, o->threads, "render threads (default: all cores)");
    cmd->callback([o] {
        if (int rc = runFit(*o)) throw CLI::RuntimeError(rc);
    });
}

}  // namespace woven
