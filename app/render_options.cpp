#include "render_options.h"

#include "threads_option.h"

namespace woven {

std::vector<CLI::Option*> addRenderOptions(CLI::App& command, RenderOptions& o) {
    const size_t before = command.get_options().size();
    addFrameOptions(command, o.frame);
    addThreadsOption(command, o.threads, "worker threads (default: all cores)");
    const std::vector<CLI::Option*> all = command.get_options();
    return {all.begin() + std::ptrdiff_t(before), all.end()};
}

}  // namespace woven
