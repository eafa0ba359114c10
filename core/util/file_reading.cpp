#include "file_reading.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace woven {

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
        fail("the file has " + std::to_string(info.st_size) + " bytes, more than the " + std::to_string(maxBytes) +
             " woven reads");
    }
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
