#include "system_memory.h"

#include <unistd.h>

#include <cstdint>

namespace woven {

size_t physicalMemoryBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? size_t(pages) * size_t(pageSize) : size_t(0);
}

std::string gibibytes(double bytes) { return std::to_string(int64_t(bytes / double(1 << 30) + 0.5)) + " GiB"; }

}  // namespace woven
