#include "threads_option.h"

#include <iostream>

#include "frame_limits.h"
#include "number_checks.h"

namespace woven {

CLI::Option* addThreadsOption(CLI::App& command, int& threads, const std::string& help) {
    return command.add_option("--threads", threads, help)->transform(wholeNumber(0))->each([](const std::string& value) {
        const int cores = workerThreads(0);
        if (std::stoll(value) > cores)
            std::cerr << "warning: --threads " << value << ": woven may use " << cores << " cores here, and renders with "
                      << cores << " threads\n";
    });
}

}  // namespace woven
