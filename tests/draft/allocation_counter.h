#pragma once
// Counts the bytes the test program holds through operator new, so a test can bound the peak
// memory of one call (the reader on files that declare 10^9 threads).
#include <cstddef>

namespace woven::test {

// Starts a new peak at the bytes held now.
void resetAllocationPeak();
// The most bytes held at once since resetAllocationPeak(), above what was held then.
size_t allocationPeakSinceReset();

}  // namespace woven::test
