#include "atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace woven {

std::string temporaryPathFor(const std::string& path) {
    return path + ".tmp-" + std::to_string(::getpid());
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& write) {
    const std::string tmp = temporaryPathFor(path);
    try {
        write(tmp);
    } catch (const std::exception& e) {
        std::remove(tmp.c_str());
        throw FileWriteError(path + ": " + e.what());
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(tmp.c_str());
        throw FileWriteError(path + ": cannot rename the temporary file into place: " + reason);
    }
}

}  // namespace woven
