#include "output_path.h"

#include <sys/stat.h>

#include <filesystem>

#include "file_reading.h"

namespace woven {

void checkOutput(const std::string& out) {
    const auto refuse = [&](const std::string& why) { throw FileWriteError(out + ": " + why); };
    if (out.empty()) refuse("an empty file name");
    struct stat info {};
    if (::stat(out.c_str(), &info) == 0) {
        if (S_ISDIR(info.st_mode)) refuse("is a directory, not a file name");
        if (!S_ISREG(info.st_mode))
            refuse("is not a regular file (a FIFO, socket or device): woven writes its outputs as regular files and "
                   "never replaces such a node; choose another output");
        if ((info.st_mode & 0222) == 0) refuse("is read-only: woven does not replace it; choose another output");
        if (readAsInput(out))
            refuse("is an input of this command: writing it would replace what it reads; choose another output");
    }
    checkWritable(out);
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code error;
    return std::filesystem::equivalent(a, b, error) && !error;
}

std::string partialName(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

}  // namespace woven
