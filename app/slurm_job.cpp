#include "slurm_job.h"

#include <cmath>
#include <sstream>

#include "shell_quote.h"

namespace woven {

namespace {

// sbatch expands %A, %a, %j ... in --output: a literal % in a folder name is written %%.
std::string sbatchFileName(const std::string& path) {
    std::string escaped;
    for (char c : path) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return escaped;
}

std::string shellArray(const std::string& name, const std::vector<std::string>& words) {
    std::string line = name + "=(";
    for (size_t i = 0; i < words.size(); ++i) line += (i ? " " : "") + shellQuote(words[i]);
    return line + ")\n";
}

// `name=(...)` holding one field of every frame, in frame order: the scripts index it by frame.
std::string frameArray(const std::string& name, const std::vector<ClusterFrame>& frames,
                       std::string ClusterFrame::*field) {
    std::vector<std::string> words;
    for (const ClusterFrame& f : frames) words.push_back(f.*field);
    return shellArray(name, words);
}

std::vector<std::string> commonSbatchArguments(const SbatchOptions& o) {
    std::vector<std::string> args;
    if (!o.partition.empty()) args.push_back("--partition=" + o.partition);
    if (!o.time.empty()) args.push_back("--time=" + o.time);
    if (o.requeue) args.push_back("--requeue");
    return args;
}

}  // namespace

SampleRange SlurmJob::taskSamples(int index) const {
    const int64_t t = index % tasks;
    const int64_t first = spp * t / tasks, end = spp * (t + 1) / tasks;
    return {first, end - first};
}

double SlurmJob::taskNoiseThreshold() const { return noiseThreshold * std::sqrt(double(tasks)); }

std::string SlurmJob::renderLog(const std::string& jobId, int index) const {
    return logFolder() + "/render_" + jobId + "_" + std::to_string(index) + ".log";
}

std::string SlurmJob::mergeLog(const std::string& jobId, int frameIndex) const {
    return logFolder() + "/merge_" + jobId + "_" + std::to_string(frameIndex) + ".log";
}

std::string SlurmJob::renderScript() const {
    std::ostringstream s;
    s << "#!/bin/bash\n"
         "# Written by woven submit. Task T of the job array renders frame T / tasks, samples\n"
         "# [spp * t / tasks, spp * (t + 1) / tasks) with t = T % tasks: a function of T alone, so a\n"
         "# requeued task renders the same samples and its part file (written atomically) replaces\n"
         "# the earlier one. Run by hand: SLURM_ARRAY_TASK_ID=T bash "
      << shellQuote(renderScriptPath()) << "\n"
      << "set -euo pipefail\n"
      << "tasks=" << tasks << "\n"
      << "spp=" << spp << "\n"
      << frameArray("scenes", frames, &ClusterFrame::scene) << frameArray("parts", frames, &ClusterFrame::parts)
      << "index=${SLURM_ARRAY_TASK_ID:?not set: submit this script with sbatch --array=0-" << renderTasks() - 1
      << "}\n"
         "frame=$((index / tasks))\n"
         "t=$((index % tasks))\n"
         "first=$((spp * t / tasks))\n"
         "end=$((spp * (t + 1) / tasks))\n"
      << "exec " << shellQuote(woven) << " render \"${scenes[frame]}\" --first-sample \"$first\" --spp \"$((end - first))\" \\\n"
      << "    -o \"${parts[frame]}/" << kPartPrefix << "${first}-$((end - 1)).exr\" --no-denoise --noise-threshold "
      << taskNoiseThreshold();
    if (!renderArguments.empty()) s << " \\\n    " << shellCommand(renderArguments);
    s << "\n";
    return s.str();
}

std::string SlurmJob::mergeScript() const {
    std::ostringstream s;
    s << "#!/bin/bash\n"
         "# Written by woven submit. Task F of the job array merges the part files of frame F (frame 0\n"
         "# when run by hand: SLURM_ARRAY_TASK_ID=F bash "
      << shellQuote(mergeScriptPath())
      << "). woven merge writes the frame only\n"
         "# when its parts hold every sample once; otherwise it names the missing samples, writes\n"
         "# OUT.partial.exr from the parts there are and fails.\n"
         "set -euo pipefail\n"
         "shopt -s nullglob extglob\n"
      << frameArray("outs", frames, &ClusterFrame::out) << frameArray("parts", frames, &ClusterFrame::parts) << "frame=${SLURM_ARRAY_TASK_ID:-0}\n"
      << "exec " << shellQuote(woven) << " merge --expect-samples " << spp << (denoise ? "" : " --no-denoise")
      << " -o \"${outs[frame]}\" \\\n"
      << "    \"${parts[frame]}\"/" << kPartPrefix << "+([0-9])-+([0-9]).exr\n";
    return s.str();
}

std::vector<std::string> SlurmJob::renderSubmission() const {
    std::vector<std::string> args = {"sbatch", "--parsable", "--job-name=woven-render",
                                     "--array=0-" + std::to_string(renderTasks() - 1),
                                     "--output=" + sbatchFileName(logFolder()) + "/render_%A_%a.log"};
    for (const std::string& a : commonSbatchArguments(sbatch)) args.push_back(a);
    if (sbatch.cpusPerTask > 0) args.push_back("--cpus-per-task=" + std::to_string(sbatch.cpusPerTask));
    for (const std::string& a : sbatch.extra) args.push_back(a);
    args.push_back(renderScriptPath());
    return args;
}

std::vector<std::string> SlurmJob::mergeSubmission(const std::string& renderJobId) const {
    // afterany, not afterok: with afterok a failed task would leave the merge pending for ever,
    // and nothing would name the missing samples or write the partial frame.
    std::vector<std::string> args = {"sbatch", "--parsable", "--job-name=woven-merge",
                                     "--array=0-" + std::to_string(frames.size() - 1),
                                     "--dependency=afterany:" + renderJobId,
                                     "--output=" + sbatchFileName(logFolder()) + "/merge_%A_%a.log"};
    for (const std::string& a : commonSbatchArguments(sbatch)) args.push_back(a);
    for (const std::string& a : sbatch.extra) args.push_back(a);
    args.push_back(mergeScriptPath());
    return args;
}

}  // namespace woven
