#include "sample_index_check.h"

#include <charconv>
#include <string>

namespace woven {

CLI::Validator sampleIndexCheck(int64_t lowest, int64_t highest) {
    const std::string range = std::to_string(lowest) + " to " + std::to_string(highest);
    return CLI::Validator(
        [=](const std::string& text) {
            int64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [last, error] = std::from_chars(text.data(), end, value);
            if (error == std::errc() && last == end && value >= lowest && value <= highest) return std::string();
            return "'" + text + "' is not a whole number from " + range;
        },
        range);
}

}  // namespace woven
