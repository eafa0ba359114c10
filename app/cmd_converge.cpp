// `woven converge`: error against a converged reference versus render time, per integrator, with
// the weave filter on and off, adaptive sampling at each noise threshold asked for and the
// denoiser on and off. It answers "which integrator, and how long for a given error" on a user's
// own scene, checks that `--integrator auto` picks the efficient one, and measures what the weave
// filter, adaptive sampling and the denoiser gain (less noise) and cost (bias: the reference is
// unfiltered, uniformly sampled and not denoised). The denoiser's rows are the same renders as the
// rows without it, denoised, their time the render's plus the denoiser's.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.h"
#include "converge_plan.h"
#include "frame_denoise.h"
#include "frame_io.h"
#include "image_io.h"
#include "integrators.h"
#include "output_path.h"
#include "render_job.h"
#include "run_process.h"
#include "scene_camera.h"
#include "scene_hash.h"
#include "scene_loader.h"

namespace woven {

namespace {

struct ErrorMetrics {
    double relMse;    // mean of (x - r)^2 / (r^2 + eps) over pixels and channels
    double relRmse;   // RMS error over the mean reference value
};

ErrorMetrics compare(const Image& image, const Image& reference) {
    // eps keeps black reference pixels from dominating relMSE (as in Rousselle et al.'s relMSE).
    constexpr double eps = 1e-2;
    double rel = 0, sq = 0, mean = 0;
    const size_t n = reference.pixels.size();
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            const double r = reference.pixels[i][c], d = double(image.pixels[i][c]) - r;
            rel += d * d / (r * r + eps);
            sq += d * d;
            mean += r;
        }
    mean /= 3.0 * n;
    return {rel / (3.0 * n), std::sqrt(sq / (3.0 * n)) / std::max(mean, 1e-12)};
}

// The energy of an image's fine detail: the sum over pixels (the border left out) and channels of
// the squared difference between a pixel and the mean of the 3 x 3 pixels around it. Against the
// reference's it tells whether a variant keeps the weave's threads (about 1), blurs them (below)
// or adds noise (above).
double detailEnergy(const Image& image) {
    double sum = 0.0;
    for (int y = 1; y + 1 < image.height; ++y)
        for (int x = 1; x + 1 < image.width; ++x) {
            glm::vec3 mean(0.0f);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) mean += image.at(x + dx, y + dy);
            const glm::vec3 d = image.at(x, y) - mean / 9.0f;
            sum += double(glm::dot(d, d));
        }
    return sum;
}

struct Timed {
    FilmImage film;
    double seconds;
    std::string integrator;
};

Timed renderFor(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o, const std::string& integrator,
                double seconds, uint64_t seed, bool filterWeave, double noiseThreshold = 0.0) {
    RenderSettings s;
    s.width = o.width;
    s.height = o.height;
    s.spp = 1 << 20;
    s.timeLimit = seconds;
    s.integrator = integrator;
    s.seed = seed;
    s.threads = o.threads;
    s.filterWeave = filterWeave;
    s.noiseThreshold = noiseThreshold;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    const auto start = std::chrono::steady_clock::now();
    job.run(cancel);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {job.snapshot(), elapsed, job.integratorName()};
}

// The reference: unfiltered path tracing and BDPT (both unbiased, so neither is favoured) merged by
// inverse variance, each integrator's variance estimated from two independent halves of its
// render; cached next to the results under a name that holds all it is a function of (the scene's
// content hash, as another scene may have the same file name, the size and the exact reference
// time) and reused when it is there. An equal-weight merge would let the noisier integrator's
// error dominate the reference on scenes where it is poor.
Image reference(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o, const std::string& stem) {
    namespace fs = std::filesystem;
    char referenceTime[32];
    *std::to_chars(referenceTime, referenceTime + sizeof referenceTime - 1, o.referenceTime).ptr = '\0';
    std::ostringstream key;
    key << stem << "_reference_" << sceneHash(*scene, sceneCamera(*scene)) << "_" << o.width << "x" << o.height << "_"
        << referenceTime << "s.exr";
    const fs::path path = fs::path(o.outDir) / key.str();
    if (fs::exists(path)) {
        std::cerr << "converge: reusing reference " << path.string() << "\n";
        return readExr(path.string()).image;
    }
    std::cerr << "converge: rendering reference (" << o.referenceTime << " s) ...\n";
    struct Part { std::vector<glm::vec3> mean; std::vector<float> count; double weight; };
    std::vector<Part> parts;
    uint64_t seed = 0x5eed0001;
    for (const IntegratorKind& kind : integratorKinds()) {
        if (!kind.make) continue;  // auto: the reference is of the integrators themselves
        const std::string integrator = kind.name;
        const Timed a = renderFor(scene, o, integrator, o.referenceTime / 4, seed++, false);
        const Timed b = renderFor(scene, o, integrator, o.referenceTime / 4, seed++, false);
        Part part;
        const size_t n = a.film.radiance.pixels.size();
        // The mean of two independent halves has a quarter of their squared difference as variance.
        double variance = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const glm::vec3 d = a.film.radiance.pixels[i] - b.film.radiance.pixels[i];
            variance += glm::dot(d, d) / 3.0;
            part.mean.push_back(0.5f * (a.film.radiance.pixels[i] + b.film.radiance.pixels[i]));
            part.count.push_back(a.film.sampleCount[i] + b.film.sampleCount[i]);
        }
        variance = variance / (4.0 * double(n));
        part.weight = 1.0 / std::max(variance, 1e-30);
        std::cerr << "converge: reference part " << integrator << ", mean pixel variance " << variance << "\n";
        parts.push_back(std::move(part));
    }
    const double total = parts[0].weight + parts[1].weight;
    ExrImage exr;
    exr.image.width = o.width;
    exr.image.height = o.height;
    for (size_t i = 0; i < parts[0].mean.size(); ++i) {
        exr.image.pixels.push_back(float(parts[0].weight / total) * parts[0].mean[i] +
                                   float(parts[1].weight / total) * parts[1].mean[i]);
        exr.sampleCount.push_back(parts[0].count[i] + parts[1].count[i]);
    }
    writeExr(path.string(), exr, ExrPrecision::Float);
    return exr.image;
}

// `text` as a string in gnuplot's script: single quotes, each one inside doubled.
std::string gnuplotString(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
}

// gnuplot draws the log-log plot, run without a shell (a scene or folder named with $ or quotes
// is a name, not a command), into the PNG's temporary name; without it the CSV is still there.
void plot(const std::string& csv, const std::string& png, const std::string& title, const std::string& names) {
    try {
        writeFileAtomically(png, [&](const std::string& tmp) {
            const std::string script =
                "set terminal pngcairo size 640,420 noenhanced; set output " + gnuplotString(tmp) + "; "
                "set datafile separator ','; set logscale xy; set grid; set key top right; "
                "set xlabel 'time (s)'; set ylabel 'relative RMSE'; set title " + gnuplotString(title) + "; "
                "plot for [name in " + gnuplotString(names) + "] " + gnuplotString(csv) +
                " using (strcol(1) eq name ? $2 : 1/0):5 with linespoints lw 2 title name";
            const int exitCode = runProcess({"gnuplot", "-e", script}).exitCode;
            if (exitCode != 0) throw FileWriteError(exitCode == 127 ? "gnuplot is not installed" : "gnuplot failed");
        });
    } catch (const FileWriteError& e) {
        std::cerr << "converge: no plot (" << e.what() << "); wrote " << csv << "\n";
    }
}

std::string onOff(bool on) { return on ? "on" : "off"; }

std::string adaptiveLabel(double threshold) {
    if (threshold <= 0.0) return "off";
    std::ostringstream s;
    s << "T = " << threshold;
    return s.str();
}

double meanSpp(const FilmImage& film) {
    double sum = 0.0;
    for (float n : film.sampleCount) sum += n;
    return film.sampleCount.empty() ? 0.0 : sum / double(film.sampleCount.size());
}

std::string seconds(double t) {
    if (!std::isfinite(t)) return "not reached (bias)";
    std::ostringstream s;
    s << std::setprecision(3) << t;
    return s.str();
}

// What one variant's renders measured, over the budgets.
struct Runs {
    std::vector<std::pair<double, double>> squaredError;  // (seconds, rel. RMSE^2)
    std::vector<double> relMse;                            // per budget
    double efficiency = 0.0;                               // of the longest run
    std::string picked;                                    // what auto chose
};

// Renders each variant for each budget (a denoised variant denoises its undenoised twin's
// render), and writes a row of the CSV and of the table for each; returns the runs by variant.
// The CSV's rows go to `partialCsv` as they are measured (an interrupted comparison leaves them
// there, under a name no finished table has) and into `csv`.
std::map<std::string, Runs> measure(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o,
                                    const std::vector<ConvergeVariant>& variants, const Image& ref,
                                    const std::string& partialCsv, std::string& csv) {
    const double referenceDetail = detailEnergy(ref);
    std::ofstream partial(partialCsv);
    const auto addRow = [&](const std::string& row) {
        csv += row;
        if (!(partial << row << std::flush)) throw FileWriteError(partialCsv + ": cannot write the file");
    };
    addRow("variant,seconds,spp,rel_mse,rel_rmse,efficiency,integrator,filter,noise_threshold,denoise,detail\n");
    std::cout << "| integrator | filter | adaptive | denoise | time (s) | mean spp | relMSE | rel. RMSE | efficiency 1/(relMSE x s) | "
                 "fine detail / reference's |\n"
              << "|---|---|---|---|---:|---:|---:|---:|---:|---:|\n";
    std::map<std::string, Runs> runs;
    uint64_t seed = 1;
    std::map<std::pair<std::string, size_t>, Timed> rendered;  // (render's variant, budget): denoised and not share it
    for (const ConvergeVariant& v : variants)
        for (size_t b = 0; b < o.budgets.size(); ++b) {
            ConvergeVariant undenoised = v;
            undenoised.denoise = false;
            const auto key = std::make_pair(undenoised.name(), b);
            if (rendered.find(key) == rendered.end())
                rendered.emplace(key, renderFor(scene, o, v.integrator, o.budgets[b], seed++, v.filter, v.threshold));
            const Timed& t = rendered.at(key);
            Image image = t.film.radiance;
            double seconds = t.seconds;
            if (v.denoise) {
                const auto start = std::chrono::steady_clock::now();
                image = denoiseBeauty(t.film.radiance, t.film.passes());
                seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            }
            const ErrorMetrics e = compare(image, ref);
            const double efficiency = 1.0 / (e.relMse * seconds);
            const double spp = meanSpp(t.film);
            const double detail = detailEnergy(image) / referenceDetail;
            std::ostringstream row;
            row << v.name() << "," << seconds << "," << spp << "," << e.relMse << "," << e.relRmse << "," << efficiency << ","
                << v.integrator << "," << onOff(v.filter) << "," << v.threshold << "," << onOff(v.denoise) << "," << detail << "\n";
            addRow(row.str());
            std::cout << "| " << v.integrator << (v.integrator == autoIntegrator().name ? " (" + t.integrator + ")" : "") << " | "
                      << onOff(v.filter) << " | " << adaptiveLabel(v.threshold) << " | " << onOff(v.denoise) << " | " << std::fixed
                      << std::setprecision(2) << seconds << " | " << std::setprecision(1) << spp << " | " << std::scientific << std::setprecision(3) << e.relMse << " | "
                      << e.relRmse << " | " << efficiency << " | " << std::fixed << std::setprecision(2) << detail << " |\n"
                      << std::defaultfloat << std::flush;
            Runs& r = runs[v.name()];
            r.squaredError.emplace_back(seconds, e.relRmse * e.relRmse);
            r.relMse.push_back(e.relMse);
            r.efficiency = efficiency;
            r.picked = t.integrator;
        }
    return runs;
}

// Each variant's fit of its error against time, and the table of the times to 5 % and 1 % from it.
std::map<std::string, ErrorFit> fitTimes(const std::vector<ConvergeVariant>& variants, std::map<std::string, Runs>& runs) {
    std::cout << "\nTime to a relative RMSE, from the fit e^2(t) = B + V/t over the runs above (B: what does not "
                 "fall with time: the filter's and the denoiser's bias, the error at which adaptive sampling stops a pixel, "
                 "and the reference's noise)\n\n"
              << "| integrator | filter | adaptive | denoise | time to 5% (s) | time to 1% (s) | floor sqrt(B) |\n"
              << "|---|---|---|---|---:|---:|---:|\n";
    std::map<std::string, ErrorFit> fits;
    for (const ConvergeVariant& v : variants) {
        const ErrorFit f = fits[v.name()] = fitError(runs[v.name()].squaredError);
        std::cout << "| " << v.integrator << " | " << onOff(v.filter) << " | " << adaptiveLabel(v.threshold) << " | "
                  << onOff(v.denoise) << " | " << seconds(f.timeTo(0.05))
                  << " | " << seconds(f.timeTo(0.01)) << " | " << std::setprecision(3) << std::sqrt(f.B) << " |\n";
    }
    return fits;
}

// One table of relMSE at equal time, per budget, of the variants `before` and `after` make of
// each integrator; none where no integrator ran both.
void compareVariants(const ConvergeOptions& o, const std::map<std::string, Runs>& runs, std::map<std::string, ErrorFit>& fits,
                     const std::string& title, const std::function<ConvergeVariant(const std::string&)>& before,
                     const std::function<ConvergeVariant(const std::string&)>& after, bool bias) {
    bool header = false;
    for (const std::string& integrator : o.integrators) {
        const ConvergeVariant vb = before(integrator), va = after(integrator);
        const auto b = runs.find(vb.name()), a = runs.find(va.name());
        if (b == runs.end() || a == runs.end() || b == a) continue;
        if (!header) {
            std::cout << "\n" << title << "\n\n| integrator | relMSE before / after at";
            for (double t : o.budgets) std::cout << " " << t << " s |";
            std::cout << " time to 1%, before / after |" << (bias ? " bias (rel. RMSE) |" : "") << "\n|---|";
            for (size_t i = 0; i <= o.budgets.size() + (bias ? 1 : 0); ++i) std::cout << "---:|";
            std::cout << "\n";
            header = true;
        }
        std::cout << "| " << integrator << " |";
        for (size_t i = 0; i < o.budgets.size(); ++i)
            std::cout << " " << std::setprecision(3) << b->second.relMse[i] / a->second.relMse[i] << " |";
        const ErrorFit &fb = fits[b->first], &fa = fits[a->first];
        const double tb = fb.timeTo(0.01), ta = fa.timeTo(0.01);
        if (std::isfinite(tb) || std::isfinite(ta)) std::cout << " " << std::setprecision(3) << tb / ta << " |";
        else std::cout << " neither reaches it |";
        if (bias) std::cout << " " << std::sqrt(std::max(0.0, fa.B - fb.B)) << " |";
        std::cout << "\n";
    }
}

// The default settings against the filter, adaptive sampling and the denoiser off, one at a
// time, from the same run: relMSE at equal time (per budget).
void compareDefaults(const ConvergeOptions& o, const std::map<std::string, Runs>& runs, std::map<std::string, ErrorFit>& fits,
                     const ConvergeDefaults& d) {
    const std::string threshold = std::to_string(d.threshold).substr(0, 4);
    compareVariants(o, runs, fits, "The weave filter: off (before) against on (after), uniform sampling, not denoised; the bias is sqrt(B_on - B_off)",
                    [&](const std::string& i) { return ConvergeVariant{i, false, 0.0, false}; },
                    [&](const std::string& i) { return ConvergeVariant{i, true, 0.0, false}; }, true);
    compareVariants(o, runs, fits, "The weave filter under the denoiser: off (before) against on (after), T = " + threshold +
                        ", denoised; the bias is sqrt(B_on - B_off)",
                    [&](const std::string& i) { return ConvergeVariant{i, false, d.threshold, true}; },
                    [&](const std::string& i) { return ConvergeVariant{i, true, d.threshold, true}; }, true);
    compareVariants(o, runs, fits, "Adaptive sampling: uniform (before) against T = " + threshold + " (after), filter off, not denoised",
                    [&](const std::string& i) { return ConvergeVariant{i, false, 0.0, false}; },
                    [&](const std::string& i) { return ConvergeVariant{i, false, d.threshold, false}; }, false);
    compareVariants(o, runs, fits, "The denoiser: off (before) against on (after), filter off, T = " + threshold +
                        "; the bias is sqrt(B_on - B_off)",
                    [&](const std::string& i) { return ConvergeVariant{i, false, d.threshold, false}; },
                    [&](const std::string& i) { return ConvergeVariant{i, false, d.threshold, true}; }, true);
    compareVariants(o, runs, fits, "The default settings (after) against --noise-threshold 0 --no-denoise without the filter (before)",
                    [&](const std::string& i) { return ConvergeVariant{i, false, 0.0, false}; },
                    [&](const std::string& i) { return ConvergeVariant{i, d.filter, d.threshold, d.denoise}; }, false);
}

// Which integrator is most efficient with the default settings, and what auto picks.
void reportMostEfficient(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o,
                         const std::map<std::string, Runs>& runs, const ConvergeDefaults& d) {
    std::string winner;
    double top = -1;
    for (const IntegratorKind& kind : integratorKinds()) {
        if (!kind.make) continue;
        const auto r = runs.find(ConvergeVariant{kind.name, d.filter, d.threshold, d.denoise}.name());
        if (r != runs.end() && r->second.efficiency > top) {
            top = r->second.efficiency;
            winner = kind.name;
        }
    }
    if (winner.empty()) return;
    const std::string autoName = autoIntegrator().name;
    const auto autoRuns = runs.find(ConvergeVariant{autoName, d.filter, d.threshold, d.denoise}.name());
    const std::string picked = autoRuns != runs.end() ? autoRuns->second.picked
                                                      : renderFor(scene, o, autoName, 0.5, 99, d.filter, d.threshold).integrator;
    std::cout << "\nmost efficient: " << winner << "; --integrator auto picks: " << picked
              << (picked == winner ? " (agrees)" : " (DISAGREES)") << "\n";
}

void runConverge(const ConvergeOptions& o) {
    namespace fs = std::filesystem;
    auto scene = std::make_shared<const SceneDescription>(loadScene(o.scene));
    std::error_code ec;
    fs::create_directories(o.outDir, ec);
    if (!fs::is_directory(o.outDir, ec)) throw std::invalid_argument(o.outDir + ": cannot make the folder");
    const std::string stem = fs::path(o.scene).stem().string();
    const std::string csvPath = (fs::path(o.outDir) / (stem + "_convergence.csv")).string();
    const std::string partialCsv = partialName(csvPath), pngPath = (fs::path(o.outDir) / (stem + "_convergence.png")).string();
    for (const std::string& out : {csvPath, partialCsv, pngPath}) checkOutput(out);
    const Image ref = reference(scene, o, stem);
    const std::vector<ConvergeVariant> variants = convergeVariants(o);
    std::string csv;
    std::map<std::string, Runs> runs = measure(scene, o, variants, ref, partialCsv, csv);
    // The whole table takes its name at once (the output rule, output_path.h), and the rows
    // written as they came go.
    writeFileAtomically(csvPath, [&](const std::string& tmp) {
        std::ofstream out(tmp);
        if (!(out << csv << std::flush)) throw FileWriteError("cannot write the file");
    });
    fs::remove(partialCsv, ec);
    std::string names;
    for (const ConvergeVariant& v : variants) names += (names.empty() ? "" : " ") + v.name();
    plot(csvPath, pngPath, stem, names);
    std::map<std::string, ErrorFit> fits = fitTimes(variants, runs);
    const ConvergeDefaults defaults = convergeDefaults(o);
    compareDefaults(o, runs, fits, defaults);
    reportMostEfficient(scene, o, runs, defaults);
}

}  // namespace

void addConvergeCommand(CLI::App& app) {
    auto o = std::make_shared<ConvergeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "converge",
        "Error against an unfiltered, uniformly sampled, undenoised converged reference versus time for each "
        "integrator, with the weave filter on and off, adaptive sampling off and on and the denoiser on and off "
        "(tables, CSV, log-log PNG)");
    addConvergeOptions(*cmd, *o);
    cmd->callback([o] { runConverge(*o); });
}

}  // namespace woven
