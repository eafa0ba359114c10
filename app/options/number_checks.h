#pragma once
// Number checks for options. CLI11's own let NaN through (every comparison with it is false, so
// `--exposure nan` gave a black frame) and print their bounds in full: "0.000000 to 1797693...",
// the largest double as 309 digits.
#include <CLI/CLI.hpp>

#include <limits>

namespace woven {

// A finite number from `lowest` to `highest` (either may be infinite: no bound on that side).
// The message names the value and the bounds as people write them: "'nan' is not a finite
// number", "'-1' is below 0".
CLI::Validator finiteNumber(double lowest = -std::numeric_limits<double>::infinity(),
                            double highest = std::numeric_limits<double>::infinity());

// A finite number above zero (a time, a scale).
CLI::Validator positiveNumber();

// A whole number from `lowest` to `highest`, for the options that count (pixels, samples,
// threads): "'2.5' is not a whole number", "'-1' is outside the range: it must be at least 0".
// It hands CLI11 the number in plain decimal, so register it with transform(), not check():
// CLI11 reads a leading 0 as octal (`--spp 010` rendered 8 samples) and "-1" into an unsigned
// option as 2^64 - 1.
CLI::Validator wholeNumber(long long lowest, long long highest = std::numeric_limits<long long>::max());

}  // namespace woven
