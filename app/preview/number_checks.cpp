#include "number_checks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace woven {

namespace {

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

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
