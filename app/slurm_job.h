#pragma once
// What `woven submit` sends to Slurm: a job array whose task T renders one sample range of
// frame T / tasks into a part file, and a merge job array, one task per frame, that starts once
// every render task has ended and merges the frame's parts (refusing, and writing
// OUT.partial.exr, when a range is missing). The render script computes a task's samples from
// its array index alone, so a requeued task renders the same samples again and its part file,
// written atomically, replaces the earlier one.
#include <string>
#include <vector>

#include "sample_range.h"

namespace woven {

struct ClusterFrame {
    int number = 0;     // the frame's number (--frames), 0 for a single frame
    std::string scene;  // absolute paths: tasks run on other machines, in other folders
    std::string out;    // the merged frame
    std::string parts;  // the folder of its part files
};

// How the jobs ask for resources: passed to sbatch.
struct SbatchOptions {
    std::string partition, time;
    int cpusPerTask = 0;              // 0: the cluster's default
    bool requeue = false;             // let Slurm requeue tasks that are pre-empted or lose their node
    std::vector<std::string> extra;   // given as they are, after woven's own
};

struct SlurmJob {
    std::string woven;   // absolute path of the woven binary the tasks run
    std::string folder;  // the job's folder: scripts and logs (parts go where ClusterFrame says)
    std::vector<ClusterFrame> frames;
    int spp = 0;         // samples per pixel of every frame
    int tasks = 0;       // render tasks per frame
    // The frame's --noise-threshold. A task adapts within its own sample range, so each gets
    // noiseThreshold * sqrt(tasks): the merge of the tasks' independent estimates then has about
    // noiseThreshold as relative error where one render of all the samples would stop.
    double noiseThreshold = 0.0;
    std::vector<std::string> renderArguments;  // given to every task's woven render as they are
    // The merged frame is denoised (woven merge's --denoise), once; the tasks never denoise
    // their parts, whose beauties the merge does not read.
    bool denoise = true;
    SbatchOptions sbatch;

    int renderTasks() const { return int(frames.size()) * tasks; }
    const ClusterFrame& taskFrame(int index) const { return frames[size_t(index / tasks)]; }
    // Samples [spp * t / tasks, spp * (t + 1) / tasks) for t = index % tasks: what the script computes.
    SampleRange taskSamples(int index) const;
    double taskNoiseThreshold() const;

    std::string renderScriptPath() const { return folder + "/render.sbatch"; }
    std::string mergeScriptPath() const { return folder + "/merge.sbatch"; }
    std::string logFolder() const { return folder + "/logs"; }
    std::string renderLog(const std::string& jobId, int index) const;
    std::string mergeLog(const std::string& jobId, int frameIndex) const;

    std::string renderScript() const;
    std::string mergeScript() const;
    // The sbatch command lines, --parsable so that they print the job id.
    std::vector<std::string> renderSubmission() const;
    std::vector<std::string> mergeSubmission(const std::string& renderJobId) const;
};

// Part file names start with this; the rest is "<first>-<last>.exr".
inline const char* const kPartPrefix = "samples_";

}  // namespace woven
