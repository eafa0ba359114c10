#pragma once
// What Slurm says about the tasks of job arrays: squeue while slurmctld still holds the jobs
// (MinJobAge after they end), else sacct where the cluster keeps accounting. `woven submit
// --wait` follows its jobs with it.
#include <string>
#include <vector>

namespace woven {

struct ArrayTask {
    std::string jobId;
    int index = 0;
    std::string state;  // Slurm's name: PENDING, RUNNING, COMPLETED, CANCELLED, ...
};

// The tasks of these job arrays that squeue, or else sacct, knows; tasks neither knows are left
// out. Throws when squeue fails for another reason (slurmctld unreachable, no squeue).
std::vector<ArrayTask> arrayTasks(const std::vector<std::string>& jobIds);

// Whether a job in this state has ended, for good or not.
bool hasEnded(const std::string& state);

}  // namespace woven
