#include "number_checks.h"

#include "short_number.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace woven {

namespace {

// The number `text` holds, if all of it is one; NaN and infinities included.
bool parseNumber(const std::string& text, double& value) {
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size();
}

}  // namespace

CLI::Validator finiteNumber(double lowest, double highest) {
    std::string range;
    if (std::isfinite(lowest) && std::isfinite(highest)) range = "from " + shortNumber(lowest) + " to " + shortNumber(highest);
    else if (std::isfinite(lowest)) range = "at least " + shortNumber(lowest);
    else if (std::isfinite(highest)) range = "at most " + shortNumber(highest);
    return CLI::Validator(
        [=](std::string& text) {
            double value = 0.0;
            if (!parseNumber(text, value)) return "'" + text + "' is not a number";
            if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
            if (value < lowest || value > highest) return "'" + text + "' is outside the range: it must be " + range;
            return std::string();
        },
        range.empty() ? "a finite number" : "a number " + range);
}

CLI::Validator wholeNumber(long long lowest, long long highest) {
    const std::string range = highest == std::numeric_limits<long long>::max()
                                  ? "at least " + std::to_string(lowest)
                                  : "from " + std::to_string(lowest) + " to " + std::to_string(highest);
    return CLI::Validator(
        [=](std::string& text) {
            char* end = nullptr;
            errno = 0;
            const long long value = std::strtoll(text.c_str(), &end, 10);
            const bool whole = !text.empty() && end == text.c_str() + text.size();
            double number = 0.0;
            if (!whole && !parseNumber(text, number)) return "'" + text + "' is not a number";
            if (!whole) return "'" + text + "' is not a whole number (it must be one " + range + ")";
            if (errno == ERANGE || value < lowest || value > highest) return "'" + text + "' is outside the range: it must be " + range;
            text = std::to_string(value);
            return std::string();
        },
        "a whole number " + range);
}

CLI::Validator positiveNumber() {
    return CLI::Validator(
        [](std::string& text) {
            double value = 0.0;
            if (!parseNumber(text, value)) return "'" + text + "' is not a number";
            if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
            if (!(value > 0.0)) return "'" + text + "' must be above 0";
            return std::string();
        },
        "a number above 0");
}

}  // namespace woven
