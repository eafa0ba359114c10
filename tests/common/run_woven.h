#pragma once
// Runs the `woven` binary under test (WOVEN_EXECUTABLE, defined by the test target) through the
// shell, as a user does, and gives each command test a folder of its own that goes when the test
// ends (temp_dir_test.h). The one helper of every test that runs woven to completion; tests/render's command tests
// that signal a running woven start it with fork and exec instead.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "temp_dir_test.h"

namespace woven::test {

struct RunResult {
    std::string out;
    int exitCode;  // -1 when it did not exit by itself (a signal)
};

// Standard output only; `args` may redirect standard error.
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

// Standard output and standard error together, in the order written.
inline RunResult runWovenCommand(const std::string& args) { return runWoven(args + " 2>&1"); }

// Its exit code; standard error goes to `errors` when given (through a file of this test
// process's own: CTest runs a suite's tests side by side).
inline int runWovenWithErrors(const std::string& args, std::string* errors = nullptr) {
    const std::string errorFile = testing::TempDir() + "woven_stderr_" + std::to_string(::getpid()) + ".txt";
    const int status = runWoven(args + " 2>" + errorFile).exitCode;
    if (errors) {
        std::ifstream in(errorFile);
        *errors = std::string(std::istreambuf_iterator<char>(in), {});
    }
    std::remove(errorFile.c_str());
    return status;
}

class CommandTest : public TempDirTest {};

}  // namespace woven::test
