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

// Whether `path` names a file this process has read with readRegularFile (by device and inode,
// through any spelling or link). Every file woven reads passes there, so this is the list of
// inputs no output may replace (output_path.h), textures and environment images included.
bool readByThisProcess(const std::string& path);

}  // namespace woven
