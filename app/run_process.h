#pragma once
// Runs a program (found on PATH) with arguments, without a shell, and collects what it prints:
// how `woven submit` talks to sbatch, squeue and sacct.
#include <string>
#include <vector>

namespace woven {

struct ProcessResult {
    int exitCode = 0;  // 127 when the program could not be started, 128 + N when killed by signal N
    std::string out, err;
};

ProcessResult runProcess(const std::vector<std::string>& argv);

}  // namespace woven
