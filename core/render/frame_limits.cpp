#include "frame_limits.h"

#include <tbb/info.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace woven {

void checkFrameFitsInMemory(int width, int height) {
    const size_t memory = physicalMemoryBytes();
    const double needed = double(width) * double(height) * double(kFrameBytesPerPixel);
    if (memory > 0 && needed > double(memory)) {
        throw std::invalid_argument("a " + std::to_string(width) + " x " + std::to_string(height) + " frame needs about " +
                                    gibibytes(needed) + " of memory while it renders (" + std::to_string(kFrameBytesPerPixel) +
                                    " bytes per pixel), more than this machine's " + gibibytes(double(memory)));
    }
}

int workerThreads(int requested) {
    // TBB's count, not std::thread's: it follows the CPUs this process may use (a Slurm task's).
    const int hardware = std::max(1, tbb::info::default_concurrency());
    return requested <= 0 ? hardware : std::min(requested, hardware);
}

}  // namespace woven
