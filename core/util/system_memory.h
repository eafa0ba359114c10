#pragma once
// How much memory this machine has: what work that could outgrow it (a frame, a bake) is
// checked against before anything is allocated.
#include <cstddef>
#include <string>

namespace woven {

// This machine's physical memory in bytes; 0 where the system does not say.
size_t physicalMemoryBytes();

// "12 GiB": a byte count as the messages of those checks give it.
std::string gibibytes(double bytes);

}  // namespace woven
