// `woven converge`'s arguments on any command line (the bytes' words between NUL bytes): parsed
// and checked as the command does (converge_plan.h), then all it works out before rendering: the
// variants, the defaults it compares against, and each variant's fit of error against time over
// made-up runs, one a budget, their squared errors the noise thresholds given (any finite value
// from 0 up, as a measured error may be).
#include "converge_plan.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> words = woven::fuzz::arguments(data, size);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    woven::ConvergeOptions o;
    CLI::App app{"converge"};
    woven::addConvergeOptions(app, o);
    woven::fuzz::refusalsAreFine([&] {
        app.parse(int(argv.size()), argv.data());
        const woven::ConvergeDefaults defaults = woven::convergeDefaults(o);
        for (const woven::ConvergeVariant& v : woven::convergeVariants(o)) {
            std::vector<std::pair<double, double>> runs;
            for (size_t b = 0; b < o.budgets.size(); ++b) runs.emplace_back(o.budgets[b], o.thresholds[b % o.thresholds.size()]);
            const woven::ErrorFit fit = woven::fitError(runs);
            (void)fit.timeTo(0.01);
            (void)v.name();
        }
        (void)defaults;
    });
    return 0;
}
