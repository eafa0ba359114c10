#include "converge_plan.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "choice_check.h"
#include "integrators.h"
#include "number_checks.h"
#include "threads_option.h"

namespace woven {

namespace {

// What --budgets and --reference-time take. A time of 0, below or NaN would set no time limit at
// all (a render then takes its 2^20 samples); below a millisecond no pass ends in time, and over a
// day is a slip of the keyboard (1e9 s is 30 years).
constexpr double kMinSeconds = 1e-3, kMaxSeconds = 86400;

// An empty list (`--budgets ""`) leaves nothing to compare, and a value twice makes two rows of
// one name whose runs are pooled as one variant's.
template <typename T>
void checkList(const std::vector<T>& values, const std::string& option) {
    if (values.empty()) throw CLI::ValidationError(option, "give at least one value");
    if (std::set<T>(values.begin(), values.end()).size() != values.size())
        throw CLI::ValidationError(option, "a value is given twice");
}

}  // namespace

void addConvergeOptions(CLI::App& cmd, ConvergeOptions& o) {
    o.integrators = integratorNames();
    cmd.add_option("scene", o.scene, "scene file (.json, .gltf, .glb)")->required();
    const CLI::Validator timeCheck = finiteNumber(kMinSeconds, kMaxSeconds);
    cmd.add_option("--budgets", o.budgets, "time budgets in seconds")->delimiter(',')->check(timeCheck);
    cmd.add_option("--integrators", o.integrators, "integrators to compare (" + integratorChoices() + ")")
        ->delimiter(',')
        ->check(oneOf(integratorNames()));
    cmd.add_option("--filter", o.filters, "the weave filter: on, off or on,off (both, compared)")
        ->delimiter(',')
        ->check(oneOf({"on", "off"}));
    cmd.add_option("--denoise", o.denoise, "the denoiser: on, off or on,off (both, from the same renders)")
        ->delimiter(',')
        ->check(oneOf({"on", "off"}));
    cmd.add_option("--noise-thresholds", o.thresholds,
                   "adaptive sampling's thresholds to compare; 0: uniform sampling (default: 0 and woven render's)")
        ->delimiter(',')
        ->check(finiteNumber(0.0));
    cmd.add_option("--reference-time", o.referenceTime, "seconds for the reference (split between integrators)")
        ->check(timeCheck);
    cmd.add_option("--width", o.width, "image width")->transform(wholeNumber(8, 8192));
    cmd.add_option("--height", o.height, "image height")->transform(wholeNumber(8, 8192));
    addThreadsOption(cmd, o.threads, "threads (0 = all cores)");
    cmd.add_option("--out-dir", o.outDir, "where the reference, CSV and plot go");
    cmd.parse_complete_callback([&o] {
        checkList(o.budgets, "--budgets");
        checkList(o.integrators, "--integrators");
        checkList(o.filters, "--filter");
        checkList(o.thresholds, "--noise-thresholds");
        checkList(o.denoise, "--denoise");
    });
}

std::string ConvergeVariant::name() const {
    std::ostringstream n;
    n << integrator << (filter ? "-filter" : "");
    if (threshold > 0.0) n << "-adaptive" << threshold;
    if (denoise) n << "-denoised";
    return n.str();
}

std::vector<ConvergeVariant> convergeVariants(const ConvergeOptions& o) {
    std::vector<ConvergeVariant> variants;
    for (const std::string& filter : o.filters)
        for (double threshold : o.thresholds)
            for (const std::string& integrator : o.integrators)
                for (const std::string& denoise : o.denoise) variants.push_back({integrator, filter == "on", threshold, denoise == "on"});
    return variants;
}

ConvergeDefaults convergeDefaults(const ConvergeOptions& o) {
    return {std::find(o.filters.begin(), o.filters.end(), "off") == o.filters.end(),
            std::find(o.denoise.begin(), o.denoise.end(), "on") != o.denoise.end(),
            std::find(o.thresholds.begin(), o.thresholds.end(), kDefaultNoiseThreshold) != o.thresholds.end()
                ? kDefaultNoiseThreshold
                : o.thresholds.front()};
}

double ErrorFit::timeTo(double target) const { return target * target > B ? V / (target * target - B) : INFINITY; }

ErrorFit fitError(const std::vector<std::pair<double, double>>& timeAndSquaredError) {
    double s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0;
    for (const auto& [t, e2] : timeAndSquaredError) {
        const double w = 1.0 / (e2 * e2), x = 1.0 / t;
        s00 += w;
        s01 += w * x;
        s11 += w * x * x;
        r0 += w * e2;
        r1 += w * e2 * x;
    }
    const double det = s00 * s11 - s01 * s01;
    ErrorFit f;
    if (timeAndSquaredError.size() >= 2 && det > 0.0) {
        f.B = (s11 * r0 - s01 * r1) / det;
        f.V = (s00 * r1 - s01 * r0) / det;
    }
    if (!(f.B > 0.0) || !(f.V > 0.0)) {
        // Noise alone (or too few runs): through the longest run with B = 0 (budgets come in any order).
        const auto& [t, e2] = *std::max_element(timeAndSquaredError.begin(), timeAndSquaredError.end());
        f = {0.0, e2 * t};
    }
    return f;
}

}  // namespace woven
