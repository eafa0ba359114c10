#include "atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "output_path.h"

namespace woven {

namespace {

namespace fs = std::filesystem;

std::string hostName() {
    char name[HOST_NAME_MAX + 1] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "localhost";
    return name;
}

// "<name>.tmp-<host>-" for `path`: what every process's temporary file of it starts with.
std::string temporaryPrefix(const std::string& path) { return fs::path(path).filename().string() + ".tmp-" + hostName() + "-"; }

// Removes the temporary files of `path` that processes of this host, now gone, left behind.
// Another host's are left alone: a PID means nothing here, and that process may be writing.
void removeStaleTemporaries(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    const std::string prefix = temporaryPrefix(path);
    std::error_code error;
    for (fs::directory_iterator it(parent.empty() ? fs::path(".") : parent, error), end; !error && it != end;
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string pid = name.substr(prefix.size());
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) continue;
        if (::kill(pid_t(std::stol(pid)), 0) != 0 && errno == ESRCH) fs::remove(it->path(), error);
    }
}

}  // namespace

std::string temporaryPathFor(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return (parent / (temporaryPrefix(path) + std::to_string(::getpid()))).string();
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& write) {
    checkOutput(path);
    removeStaleTemporaries(path);
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

void checkWritable(const std::string& path) {
    const std::string tmp = temporaryPathFor(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        const std::string folder = fs::path(path).parent_path().string();
        throw FileWriteError(path + ": cannot write in the folder '" + (folder.empty() ? "." : folder) +
                             "': " + std::strerror(errno));
    }
    ::close(fd);
    std::remove(tmp.c_str());
}

}  // namespace woven
