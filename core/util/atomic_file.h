#pragma once
// Writing a file so that its final name only ever holds a complete file: the content goes to
// "<path>.tmp-<host>-<pid>" and is renamed over <path> once written. A reader (or a crash, or
// Ctrl-C) never sees a half-written file under the final name. A process killed outright
// (SIGKILL, a node lost) leaves its temporary file behind: the next write of the same path on
// the same host removes those whose process is gone.
#include <functional>
#include <stdexcept>
#include <string>

namespace woven {

struct FileWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The temporary name used for `path` by this process.
std::string temporaryPathFor(const std::string& path);

// Checks `path` as an output (checkOutput(), output_path.h), calls write(tmpPath), then renames
// tmpPath to path. When the check or `write` throws, or the rename fails, the temporary file is
// removed and FileWriteError (naming `path`) is thrown.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& write);

// Throws the FileWriteError a write of `path` would meet for want of a folder or permission, by
// creating and removing its temporary file (part of checkOutput()).
void checkWritable(const std::string& path);

}  // namespace woven
