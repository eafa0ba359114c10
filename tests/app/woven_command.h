#pragma once
// Runs the `woven` binary under test (WOVEN_BINARY) as a child process, and gives each test a
// folder of its own that goes when the test ends.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace woven::test {

struct CommandResult {
    int status;          // as pclose gives it: 0 for success
    std::string output;  // stdout and stderr
};

inline CommandResult runWovenCommand(const std::string& args) {
    const std::string cmd = std::string(WOVEN_BINARY) + " " + args + " 2>&1";
    CommandResult result{-1, ""};
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
    result.status = pclose(pipe);
    return result;
}

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
