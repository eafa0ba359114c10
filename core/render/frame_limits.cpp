#include "frame_limits.h"

#include <tbb/info.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace woven {

size_t physicalMemoryBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? size_t(pages) * size_t(pageSize) : size_t(0);
}

void checkFrameFitsInMemory(int width, int height) {
    const size_t memory = physicalMemoryBytes();
    const double needed = double(width) * double(height) * double(kFrameBytesPerPixel);
    if (memory > 0 && needed > double(memory)) {
        const auto gib = [](double bytes) { return std::to_string(int64_t(bytes / double(1 << 30) + 0.5)) + " GiB"; };
        throw std::invalid_argument("a " + std::to_string(width) + " x " + std::to_string(height) + " frame needs about " +
                                    gib(needed) + " of memory while it renders (" + std::to_string(kFrameBytesPerPixel) +
                                    " bytes per pixel), more than this machine's " + gib(double(memory)));
    }
}

int workerThreads(int requested) {
    // TBB's count, not std::thread's: it follows the CPUs this process may use (a Slurm task's).
    const int hardware = std::max(1, tbb::info::default_concurrency());
    return requested <= 0 ? hardware : std::min(requested, hardware);
}

}  // namespace woven
