#pragma once
// Writing a file so that its final name only ever holds a complete file: the content goes to
// "<path>.tmp-<pid>" and is renamed over <path> once written. A reader (or a crash, or Ctrl-C)
// never sees a half-written file under the final name.
#include <functional>
#include <stdexcept>
#include <string>

namespace woven {

struct FileWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The temporary name used for `path` by this process.
std::string temporaryPathFor(const std::string& path);

// Calls write(tmpPath), then renames tmpPath to path. When `write` throws, or the rename fails,
// the temporary file is removed and FileWriteError (naming `path`) is thrown.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& write);

}  // namespace woven
