#pragma once
// The check of options that count samples in 64 bits (--first-sample, --expect-samples): CLI11
// says only "Could not convert" for a number past int, and its ranges print in its own words.
#include <CLI/CLI.hpp>

#include <cstdint>

namespace woven {

// A whole number from `lowest` to `highest`; the message names the value and both bounds.
CLI::Validator sampleIndexCheck(int64_t lowest, int64_t highest);

}  // namespace woven
