#include "slurm_queue.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

#include "run_process.h"

namespace woven {

namespace {

std::string joinIds(const std::vector<std::string>& ids) {
    std::string list;
    for (const std::string& id : ids) list += (list.empty() ? "" : ",") + id;
    return list;
}

// Lines "<job>_<index><separator><state>[ by ...]"; other lines (a pending array's summary
// "<job>_[0-3]", job steps) are skipped.
std::vector<ArrayTask> parseTasks(const std::string& output, char separator) {
    std::vector<ArrayTask> tasks;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        const size_t split = line.find(separator), underscore = line.find('_');
        if (split == std::string::npos || underscore == std::string::npos || underscore > split) continue;
        const std::string index = line.substr(underscore + 1, split - underscore - 1);
        if (index.empty() || !std::all_of(index.begin(), index.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        std::istringstream rest(line.substr(split + 1));
        ArrayTask task;
        task.jobId = line.substr(0, underscore);
        task.index = std::stoi(index);
        rest >> task.state;  // sacct writes "CANCELLED by 0"
        if (!task.state.empty()) tasks.push_back(task);
    }
    return tasks;
}

}  // namespace

std::vector<ArrayTask> arrayTasks(const std::vector<std::string>& jobIds) {
    const std::string ids = joinIds(jobIds);
    const ProcessResult squeue = runProcess({"squeue", "--noheader", "--array", "--states=all", "--jobs=" + ids,
                                             "--format=%i %T"});
    // squeue fails with "Invalid job id specified" once slurmctld has forgotten every job asked for.
    if (squeue.exitCode != 0 && squeue.err.find("Invalid job id") == std::string::npos)
        throw std::runtime_error("squeue failed: " +
                                 (squeue.err.empty() ? "exit status " + std::to_string(squeue.exitCode) : squeue.err));
    std::vector<ArrayTask> tasks = squeue.exitCode == 0 ? parseTasks(squeue.out, ' ') : std::vector<ArrayTask>();

    std::set<std::string> known;
    for (const ArrayTask& t : tasks) known.insert(t.jobId);
    if (known.size() == jobIds.size()) return tasks;
    // slurmctld has forgotten a job (it keeps ended jobs MinJobAge seconds): ask the accounting.
    const ProcessResult sacct = runProcess({"sacct", "--noheader", "--parsable2", "--allocations", "--jobs=" + ids,
                                            "--format=JobID,State"});
    if (sacct.exitCode != 0) return tasks;
    for (const ArrayTask& t : parseTasks(sacct.out, '|'))
        if (!known.count(t.jobId)) tasks.push_back(t);
    return tasks;
}

bool hasEnded(const std::string& state) {
    static const std::set<std::string> ended = {"COMPLETED", "FAILED",        "CANCELLED", "TIMEOUT",
                                                "NODE_FAIL", "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE",
                                                "PREEMPTED", "REVOKED"};
    return ended.count(state) > 0;
}

}  // namespace woven
