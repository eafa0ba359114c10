#include "bobyqa.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>

namespace woven {

namespace {

double trampoline(const std::vector<double>& x, std::vector<double>&, void* data) {
    return (*static_cast<const Objective*>(data))(x);
}

}  // namespace

int minimiseInUnitBox(std::vector<double>& x, const Objective& objective, int evaluations,
                      const std::function<bool()>& stop) {
    nlopt::opt opt(nlopt::LN_BOBYQA, unsigned(x.size()));
    opt.set_lower_bounds(std::vector<double>(x.size(), 0.0));
    opt.set_upper_bounds(std::vector<double>(x.size(), 1.0));
    int count = 0;
    std::vector<double> best = x;
    double bestValue = INFINITY;
    const Objective counted = [&](const std::vector<double>& v) {
        if (stop()) throw nlopt::forced_stop();
        ++count;
        const double f = objective(v);
        if (f < bestValue) {
            bestValue = f;
            best = v;
        }
        return f;
    };
    opt.set_min_objective(trampoline, const_cast<Objective*>(&counted));
    if (evaluations > 0) opt.set_maxeval(evaluations);
    opt.set_initial_step(0.08);
    opt.set_xtol_rel(1e-4);
    for (double& v : x) v = std::clamp(v, 0.0, 1.0);
    double f = 0.0;
    try {
        opt.optimize(x, f);
    } catch (const std::runtime_error&) {
        // forced_stop (the budget, Ctrl-C) or roundoff_limited: the best point so far stands.
    }
    if (std::isfinite(bestValue)) x = best;
    return count;
}

}  // namespace woven
