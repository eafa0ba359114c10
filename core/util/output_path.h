#pragma once
// The one rule every output of every command follows (docs/LIMITS.md). An output names a regular
// file or nothing yet: never a FIFO, a device or a folder (the atomic write's rename would
// replace the node itself: run as root, `fit -o /dev/full` turned the device into a JSON file),
// never a read-only file, and never a file the command has read (readAsInput(), file_reading.h:
// its scene, glTF, buffers, textures, environment image, photos, drafts); and its folder may be
// written.
// Commands check each output before any work; writeFileAtomically checks again as it writes.
#include <string>

#include "atomic_file.h"

namespace woven {

// Throws FileWriteError naming `out` and why it cannot be written.
void checkOutput(const std::string& out);

// Whether the two paths name one existing file (through any spelling or link).
bool sameFile(const std::string& a, const std::string& b);

// "out.exr" -> "out.partial.exr": where unfinished work goes, so it never takes the name of a
// finished one.
std::string partialName(const std::string& path);

}  // namespace woven
