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

// While on, every file readRegularFile reads is remembered: a command's inputs, none of which
// its outputs may replace (output_path.h). main() turns it on for the command it runs; off (the
// library in tests, the previewer's window, which saves a material or draft back to the file it
// opened, as its user asks), nothing is remembered.
void rememberInputs(bool on);

// Whether `path` names a file remembered as read (by device and inode, through any spelling or
// link). Every file woven reads passes through readRegularFile, so these are all of a command's
// inputs: scene, glTF, buffers, textures, environment image, photos, drafts.
bool readAsInput(const std::string& path);

}  // namespace woven
