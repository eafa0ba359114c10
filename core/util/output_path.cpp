#include "output_path.h"

#include <filesystem>

namespace woven {

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code error;
    return std::filesystem::equivalent(a, b, error) && !error;
}

void refuseOverwritingInputs(const std::string& out, const std::vector<std::string>& inputs) {
    for (const std::string& input : inputs)
        if (sameFile(out, input))
            throw FileWriteError(out + ": is " + (input == out ? "an input" : "an input (" + input + ")") +
                                 " of this command: writing it would replace what it reads; choose another output");
}

}  // namespace woven
