#pragma once
// Reading a whole file that someone else made: only a regular file (a FIFO would block for
// ever, a directory or a device is no input), only up to a size the caller allows, checked
// before anything is allocated. Errors throw FileReadError "<path>: <problem>".
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace woven {

struct FileReadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::vector<unsigned char> readRegularFile(const std::string& path, size_t maxBytes);

}  // namespace woven
