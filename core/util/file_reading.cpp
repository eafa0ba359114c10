#include "file_reading.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <utility>

namespace woven {

namespace {
// "64 MiB", "2 GiB", or a count of bytes.
std::string byteSize(size_t bytes) {
    if (bytes >= (size_t(1) << 30) && bytes % (size_t(1) << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
    if (bytes >= (size_t(1) << 20) && bytes % (size_t(1) << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

using FileId = std::pair<dev_t, ino_t>;

std::mutex readFilesMutex;
bool remembering = false;
std::set<FileId> readFiles;

void rememberRead(const struct stat& info) {
    const std::lock_guard<std::mutex> lock(readFilesMutex);
    if (remembering) readFiles.insert({info.st_dev, info.st_ino});
}
}  // namespace

void rememberInputs(bool on) {
    const std::lock_guard<std::mutex> lock(readFilesMutex);
    remembering = on;
    if (!on) readFiles.clear();
}

bool readAsInput(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return false;
    const std::lock_guard<std::mutex> lock(readFilesMutex);
    return readFiles.count({info.st_dev, info.st_ino}) > 0;
}

std::vector<unsigned char> readRegularFile(const std::string& path, size_t maxBytes) {
    const auto fail = [&](const std::string& problem) { throw FileReadError(path + ": " + problem); };
    // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat then says what it is.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) fail(errno == ENOENT ? "no such file" : std::string("cannot open the file: ") + std::strerror(errno));
    struct stat info {};
    if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        fail(S_ISDIR(info.st_mode) ? "is a directory, not a file" : "is not a regular file (a pipe, socket or device)");
    }
    if (size_t(info.st_size) > maxBytes) {
        ::close(fd);
        fail("larger than woven's limit of " + byteSize(maxBytes) + " (" + std::to_string(info.st_size) + " bytes)");
    }
    rememberRead(info);
    std::vector<unsigned char> bytes(size_t(info.st_size));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ::close(fd);
            fail(n < 0 ? std::string("cannot read the file: ") + std::strerror(errno) : "the file shrank while being read");
        }
        done += size_t(n);
    }
    ::close(fd);
    return bytes;
}

}  // namespace woven
