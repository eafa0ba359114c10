#pragma once
// What `woven converge` measures, before it renders anything: its options, their checks, the
// variants they make (integrator x weave filter x noise threshold x denoiser), the defaults the
// comparisons are made against, and the fit of each variant's error against time. Apart from the
// rendering so that fuzz/fuzz_converge runs all of it on any arguments.
#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

#include "render_job.h"

namespace woven {

struct ConvergeOptions {
    std::string scene, outDir = "converge";
    std::vector<double> budgets{1, 2, 4, 8, 16};
    std::vector<std::string> integrators;                           // every integrator (addConvergeOptions)
    std::vector<std::string> filters{"on", "off"};                  // the weave filter (--filter is "on")
    std::vector<double> thresholds{0.0, kDefaultNoiseThreshold};    // adaptive sampling; 0: off
    std::vector<std::string> denoise{"on", "off"};                  // the denoiser (woven render's default is on)
    double referenceTime = 300;
    int width = 320, height = 240;
    int threads = 0;
};

// Registers the scene and every option on `command`, with their checks: each list holds at least
// one value, each value once (CLI::ValidationError naming the option otherwise).
void addConvergeOptions(CLI::App& command, ConvergeOptions& options);

// One integrator with the filter on or off, a noise threshold and the denoiser on or off, as a
// row of the tables and a line of the plot.
struct ConvergeVariant {
    std::string integrator;
    bool filter;
    double threshold;  // 0: uniform sampling
    bool denoise;
    std::string name() const;
};

// Every variant of the options: each filter, noise threshold and integrator, the denoised one
// right after the same render's undenoised one.
std::vector<ConvergeVariant> convergeVariants(const ConvergeOptions& options);

// The settings woven render takes by default, of those the options compare.
struct ConvergeDefaults {
    bool filter, denoise;
    double threshold;
};
ConvergeDefaults convergeDefaults(const ConvergeOptions& options);

// Squared relative RMSE against time, e^2(t) = B + V / t, fitted by least squares weighted by
// 1 / e^2 (each run's error is known to a relative precision): V is the noise, B what does not
// fall with time: the filter's bias squared plus the reference's own noise (equal for every
// variant, so the difference of B between filter on and off is the filter's bias squared).
struct ErrorFit {
    double B = 0.0, V = 0.0;
    // Seconds to reach relative RMSE `target`; infinity where the floor B is above it.
    double timeTo(double target) const;
};

// From at least one run (seconds, relative RMSE squared), each time above 0.
ErrorFit fitError(const std::vector<std::pair<double, double>>& timeAndSquaredError);

}  // namespace woven
