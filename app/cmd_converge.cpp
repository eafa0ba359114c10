// `woven converge`: error against a converged reference versus render time, per integrator.
// It answers "which integrator, and how long for a given error" on a user's own scene, and
// checks that `--integrator auto` picks the efficient one.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "commands.h"
#include "image_io.h"
#include "render_job.h"
#include "scene_loader.h"

namespace woven {

namespace {

struct ConvergeOptions {
    std::string scene, outDir = "converge";
    std::vector<double> budgets{1, 2, 4, 8, 16};
    std::vector<std::string> integrators{"path", "bdpt"};
    double referenceTime = 300;
    int width = 320, height = 240;
    int threads = 0;
};

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

struct Timed {
    FilmImage film;
    double seconds;
    std::string integrator;
};

Timed renderFor(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o, const std::string& integrator,
                double seconds, uint64_t seed) {
    RenderSettings s;
    s.width = o.width;
    s.height = o.height;
    s.spp = 1 << 20;
    s.timeLimit = seconds;
    s.integrator = integrator;
    s.seed = seed;
    s.threads = o.threads;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    const auto start = std::chrono::steady_clock::now();
    job.run(cancel);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {job.snapshot(), elapsed, job.integratorName()};
}

// The reference: path tracing and BDPT (both unbiased, so neither is favoured) merged by
// inverse variance, each integrator's variance estimated from two independent halves of its
// render; cached next to the results and reused when its settings match. An equal-weight merge
// would let the noisier integrator's error dominate the reference on scenes where it is poor.
Image reference(std::shared_ptr<const SceneDescription> scene, const ConvergeOptions& o, const std::string& stem) {
    namespace fs = std::filesystem;
    std::ostringstream key;
    key << stem << "_" << o.width << "x" << o.height << "_" << int(o.referenceTime) << "s_reference.exr";
    const fs::path path = fs::path(o.outDir) / key.str();
    if (fs::exists(path)) {
        std::cerr << "converge: reusing reference " << path.string() << "\n";
        return readExr(path.string()).image;
    }
    std::cerr << "converge: rendering reference (" << o.referenceTime << " s) ...\n";
    struct Part { std::vector<glm::vec3> mean; std::vector<float> count; double weight; };
    std::vector<Part> parts;
    uint64_t seed = 0x5eed0001;
    for (const char* integrator : {"path", "bdpt"}) {
        const Timed a = renderFor(scene, o, integrator, o.referenceTime / 4, seed++);
        const Timed b = renderFor(scene, o, integrator, o.referenceTime / 4, seed++);
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

void plot(const std::string& csv, const std::string& png, const std::string& title) {
    // gnuplot draws the log-log plot; without it the CSV is still there.
    std::ostringstream cmd;
    cmd << "gnuplot -e \"set terminal pngcairo size 640,420 noenhanced; set output '" << png << "'; "
        << "set datafile separator ','; set logscale xy; set grid; set key top right; "
        << "set xlabel 'time (s)'; set ylabel 'relative RMSE'; set title '" << title << "'; "
        << "plot for [name in 'path bdpt'] '" << csv << "' using (strcol(1) eq name ? \\$2 : 1/0):5 "
        << "with linespoints lw 2 title name\" 2>/dev/null";
    if (std::system(cmd.str().c_str()) != 0)
        std::cerr << "converge: gnuplot not available, wrote " << csv << " only\n";
}

void runConverge(const ConvergeOptions& o) {
    namespace fs = std::filesystem;
    auto scene = std::make_shared<const SceneDescription>(loadScene(o.scene));
    fs::create_directories(o.outDir);
    const std::string stem = fs::path(o.scene).stem().string();
    const Image ref = reference(scene, o, stem);

    const std::string csvPath = (fs::path(o.outDir) / (stem + "_convergence.csv")).string();
    std::ofstream csv(csvPath);
    csv << "integrator,seconds,spp,rel_mse,rel_rmse,efficiency\n";
    std::cout << "| integrator | time (s) | spp | relMSE | rel. RMSE | efficiency 1/(relMSE x s) |\n"
              << "|---|---:|---:|---:|---:|---:|\n";
    struct Best { double efficiency = 0, timeToOnePercent = 0; };
    std::map<std::string, Best> best;
    uint64_t seed = 1;
    for (const std::string& integrator : o.integrators)
        for (double budget : o.budgets) {
            const Timed t = renderFor(scene, o, integrator, budget, seed++);
            const ErrorMetrics e = compare(t.film.radiance, ref);
            const double efficiency = 1.0 / (e.relMse * t.seconds);
            const double spp = t.film.sampleCount.empty() ? 0.0 : t.film.sampleCount[0];
            csv << integrator << "," << t.seconds << "," << spp << "," << e.relMse << "," << e.relRmse << ","
                << efficiency << "\n";
            std::cout << "| " << integrator << " | " << std::fixed << std::setprecision(2) << t.seconds << " | "
                      << int(spp) << " | " << std::scientific << std::setprecision(3) << e.relMse << " | "
                      << e.relRmse << " | " << efficiency << " |\n" << std::defaultfloat;
            // Unbiased Monte Carlo: RMSE falls as 1/sqrt(time); the longest run extrapolates best.
            best[integrator].efficiency = efficiency;
            best[integrator].timeToOnePercent = t.seconds * std::pow(e.relRmse / 0.01, 2.0);
        }
    csv.close();
    plot(csvPath, (fs::path(o.outDir) / (stem + "_convergence.png")).string(), stem);

    std::string winner;
    double top = -1;
    std::cout << "\n| integrator | time to 1% relative RMSE (s, extrapolated from the longest run) |\n|---|---:|\n";
    for (const auto& [name, b] : best) {
        std::cout << "| " << name << " | " << std::setprecision(3) << b.timeToOnePercent << " |\n";
        if (b.efficiency > top) { top = b.efficiency; winner = name; }
    }
    const Timed autoRun = renderFor(scene, o, "auto", 0.5, 99);
    std::cout << "\nmost efficient: " << winner << "; --integrator auto picks: " << autoRun.integrator
              << (autoRun.integrator == winner ? " (agrees)" : " (DISAGREES)") << "\n";
}

}  // namespace

void addConvergeCommand(CLI::App& app) {
    auto o = std::make_shared<ConvergeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "converge", "Error against a converged reference versus time for each integrator (table, CSV, log-log PNG)");
    cmd->add_option("scene", o->scene, "scene file (.json, .gltf, .glb)")->required();
    cmd->add_option("--budgets", o->budgets, "time budgets in seconds")->delimiter(',');
    cmd->add_option("--integrators", o->integrators, "integrators to compare")->delimiter(',');
    cmd->add_option("--reference-time", o->referenceTime, "seconds for the reference (split between integrators)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--width", o->width, "image width")->check(CLI::Range(8, 8192));
    cmd->add_option("--height", o->height, "image height")->check(CLI::Range(8, 8192));
    cmd->add_option("--threads", o->threads, "threads (0 = all cores)");
    cmd->add_option("--out-dir", o->outDir, "where the reference, CSV and plot go");
    cmd->callback([o] { runConverge(*o); });
}

}  // namespace woven
