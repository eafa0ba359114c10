#pragma once
// Runs the `woven` binary under test (WOVEN_EXECUTABLE, defined by the test target) through the
// shell and collects its standard output; `args` may redirect standard error.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace woven::test {

struct RunResult {
    std::string out;
    int exitCode;
};

inline RunResult runWoven(const std::string& args) {
    const std::string command = std::string("'") + WOVEN_EXECUTABLE + "' " + args;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {"", -1};
    std::string out;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    const int status = pclose(pipe);
    return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

}  // namespace woven::test
