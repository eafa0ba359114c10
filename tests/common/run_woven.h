#pragma once
// Runs the `woven` binary under test (WOVEN_EXECUTABLE, defined by the test target) through the
// shell, as a user does, and gives each command test a folder of its own that goes when the test
// ends. The one helper of every test that runs woven to completion; tests/render's command tests
// that signal a running woven start it with fork and exec instead.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

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

class CommandTest : public testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("woven_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string file(const std::string& name) const { return (dir_ / name).string(); }

    std::filesystem::path dir_;
};

}  // namespace woven::test
