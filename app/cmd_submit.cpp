// `woven submit SCENE... --tasks N -o OUT.exr`: renders a frame, or the frames of an animation,
// on a Slurm cluster. Each frame's samples are split over N tasks of one job array (each task
// is `woven render --first-sample F --spp K` with the render options given here, passed on as
// they were typed), and a merge job per frame joins the parts exactly (slurm_job.h). docs/CLUSTER.md
// tells how to use it.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "output_path.h"
#include "commands.h"
#include "number_checks.h"
#include "frame_pattern.h"
#include "frame_io.h"
#include "image_io.h"
#include "integrators.h"
#include "render_options.h"
#include "run_process.h"
#include "scene_loader.h"
#include "shell_quote.h"
#include "slurm_job.h"
#include "slurm_queue.h"

namespace woven {

namespace {

namespace fs = std::filesystem;

struct SubmitOptions {
    std::vector<std::string> scenes;
    std::string out, frames, jobDir;
    int tasks = 0;
    RenderOptions render;
    std::vector<std::string> renderArguments;  // the render options as typed
    SbatchOptions sbatch;
    bool wait = false, dryRun = false;
    double waitTimeout = 0.0;  // seconds; 0: no limit
};

std::string absolute(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

// "A..B" -> {A, B}.
std::pair<int, int> parseFrameRange(const std::string& text) {
    static const std::regex range(R"((\d+)\.\.(\d+))");
    std::smatch m;
    if (!std::regex_match(text, m, range))
        throw std::invalid_argument("--frames " + text + ": expected A..B, two whole numbers, e.g. 1..240");
    // Frame numbers go into file names through a %d field: at most 9 digits.
    if (m[1].length() > 9 || m[2].length() > 9)
        throw std::invalid_argument("--frames " + text + ": frame numbers are at most 999999999");
    if (std::stoi(m[1]) > std::stoi(m[2]))
        throw std::invalid_argument("--frames " + text + ": the first frame is after the last (A..B needs A <= B)");
    return {std::stoi(m[1]), std::stoi(m[2])};
}

// The frames to render: one SCENE; one SCENE with a frame number field and --frames A..B; or
// several SCENEs, numbered by --frames A..B or else from 0. Numbered frames need a field in OUT.
// Sets the job's folder: --job-dir, else OUT's name (its field replaced by "A-B") with .slurm.
std::vector<ClusterFrame> resolveFrames(const SubmitOptions& o, std::string* jobDir) {
    std::vector<std::string> scenes = o.scenes;
    int firstNumber = 0;
    if (!o.frames.empty()) {
        const auto [a, b] = parseFrameRange(o.frames);
        firstNumber = a;
        if (o.scenes.size() == 1) {
            const std::optional<FramePattern> scene = FramePattern::parse(o.scenes.front());
            if (!scene)
                throw std::invalid_argument("--frames " + o.frames + ": SCENE " + o.scenes.front() +
                                            " has no frame number field such as scene_%04d.json (or give one SCENE per frame)");
            scenes.clear();
            for (int n = a; n <= b; ++n) scenes.push_back(scene->name(n));
        } else if (int(o.scenes.size()) != b - a + 1) {
            throw std::invalid_argument("--frames " + o.frames + " numbers " + std::to_string(b - a + 1) + " frames, but " +
                                        std::to_string(o.scenes.size()) + " SCENEs were given");
        }
    }
    for (const std::string& scene : scenes)
        if (!fs::is_regular_file(scene)) throw std::invalid_argument(scene + ": no such scene file");

    if (fs::path(o.out).extension() != ".exr")
        throw std::invalid_argument(o.out + ": woven submit writes EXR (the merge needs each part's sample sums): name it .exr");
    const bool numbered = !o.frames.empty() || scenes.size() > 1;
    std::optional<FramePattern> outPattern;
    fs::path named = absolute(o.out);
    if (numbered) {
        outPattern = FramePattern::parse(o.out);
        if (!outPattern)
            throw std::invalid_argument("-o " + o.out +
                                        ": with several frames, OUT needs a frame number field such as frame_%04d.exr");
        const int last = firstNumber + int(scenes.size()) - 1;
        named = absolute(outPattern->withField(std::to_string(firstNumber) + "-" + std::to_string(last)));
    }
    *jobDir = o.jobDir.empty() ? (named.parent_path() / named.stem()).string() + ".slurm" : absolute(o.jobDir);

    std::vector<ClusterFrame> frames;
    for (size_t i = 0; i < scenes.size(); ++i) {
        ClusterFrame f;
        f.number = firstNumber + int(i);
        f.scene = absolute(scenes[i]);
        f.out = numbered ? absolute(outPattern->name(f.number)) : named.string();
        f.parts = numbered ? *jobDir + "/parts/" + std::to_string(f.number) : *jobDir + "/parts";
        frames.push_back(f);
    }
    return frames;
}

SlurmJob planJob(const SubmitOptions& o) {
    SlurmJob job;
    job.frames = resolveFrames(o, &job.folder);
    job.woven = fs::read_symlink("/proc/self/exe").string();
    job.tasks = o.tasks;
    job.renderArguments = o.renderArguments;
    job.denoise = o.render.frame.denoise;
    job.sbatch = o.sbatch;

    // The first frame's scene, with the --woven edits: bad options fail here rather than in
    // every task, and it gives the samples per pixel when --spp does not.
    SceneDescription scene = loadScene(job.frames.front().scene, o.render.frame.load);
    applySceneOptions(scene, o.render.frame);
    const RenderSettings settings = frameSettings(scene, o.render.frame);
    job.spp = settings.spp;
    job.noiseThreshold = settings.noiseThreshold;
    if (job.tasks > job.spp)
        throw std::invalid_argument("--tasks " + std::to_string(job.tasks) + " is more than the " +
                                    std::to_string(job.spp) + " samples per pixel: each task needs one at least");
    if (settings.integrator == autoIntegrator().name)
        std::cerr << "note: the integrator is auto, which each task picks by timing a pilot: give --integrator path or "
                     "bdpt for a frame that equals a local render bit for bit\n";
    return job;
}

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream file(tmp);
        file << text;
        if (!file.flush()) throw std::runtime_error("cannot write the file");
    });
}

// Makes the folder `path` (and those above it), or throws naming it and the option it is for.
void makeFolder(const fs::path& path, const std::string& option) {
    if (path.empty()) return;
    std::error_code ec;
    if (fs::exists(path, ec) && !fs::is_directory(path, ec))
        throw std::invalid_argument(option + " " + path.string() + ": is a file, not a folder");
    fs::create_directories(path, ec);
    if (!fs::is_directory(path, ec))
        throw std::invalid_argument(option + " " + path.string() + ": cannot make the folder" + (ec ? ": " + ec.message() : ""));
}

// Folders and scripts, on the file system every node shares. Each frame's output is checked as
// an output now (output_path.h), not when the merge job runs.
void writeJobFiles(const SlurmJob& job) {
    makeFolder(job.folder, "--job-dir");
    makeFolder(job.logFolder(), "--job-dir");
    for (const ClusterFrame& f : job.frames) {
        makeFolder(f.parts, "--job-dir");
        makeFolder(fs::path(f.out).parent_path(), "-o");
        checkOutput(f.out);
    }
    writeText(job.renderScriptPath(), job.renderScript());
    writeText(job.mergeScriptPath(), job.mergeScript());
}

// Parts and partial frames of an earlier submission of the same frames would overlap this
// one's, or look like its result.
void removeEarlierResults(const SlurmJob& job) {
    int removed = 0;
    for (const ClusterFrame& f : job.frames) {
        for (const fs::directory_entry& entry : fs::directory_iterator(f.parts))
            if (entry.path().filename().string().rfind(kPartPrefix, 0) == 0) removed += fs::remove(entry.path());
        removed += fs::remove(partialName(f.out));
    }
    if (removed > 0) std::cerr << "removed " << removed << " files left by an earlier submission of these frames\n";
}

std::string submit(const std::vector<std::string>& command) {
    const ProcessResult r = runProcess(command);
    std::cerr << r.err;
    std::string id = r.out.substr(0, r.out.find_first_of(";\n"));  // --parsable: "id" or "id;cluster"
    if (r.exitCode != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error("sbatch failed (exit status " + std::to_string(r.exitCode) + "): " + shellCommand(command));
    return id;
}

std::string lastLine(const std::string& path) {
    std::ifstream file(path);
    std::string line, last;
    while (std::getline(file, line))
        if (!line.empty()) last = line;
    return last;
}

using Clock = std::chrono::steady_clock;

// Follows the jobs until every merge task has ended; returns whether every frame was written.
bool waitForJobs(const SlurmJob& job, const std::string& renderId, const std::string& mergeId, double timeout) {
    const Clock::time_point start = Clock::now();
    std::string lastSummary;
    std::map<int, std::string> renderStates, mergeStates;
    for (;;) {
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        try {
            for (const ArrayTask& t : arrayTasks({renderId, mergeId}))
                (t.jobId == renderId ? renderStates : mergeStates)[t.index] = t.state;
        } catch (const std::exception& e) {
            std::cerr << "woven submit: " << e.what() << " (trying again)\n";
        }
        std::map<std::string, int> counts;
        for (const auto& [index, state] : renderStates) ++counts[state];
        std::ostringstream summary;
        summary << "render tasks:";
        for (const auto& [state, n] : counts) summary << " " << n << " " << state;
        if (renderStates.empty()) summary << " not known yet";
        summary << "; merge:";
        for (const auto& [index, state] : mergeStates) summary << " " << state;
        if (summary.str() != lastSummary) {
            lastSummary = summary.str();
            std::cerr << "[" << int(elapsed) << " s] " << lastSummary << "\n";
        }
        bool ended = int(mergeStates.size()) == int(job.frames.size());
        for (const auto& [index, state] : mergeStates) ended = ended && hasEnded(state);
        if (ended) break;
        if (timeout > 0.0 && elapsed >= timeout)
            throw std::runtime_error("gave up waiting after " + std::to_string(int(timeout)) +
                                     " s; the jobs go on: squeue --jobs=" + renderId + "," + mergeId);
        // Often at first, when the small jobs of a test end, then every 10 s at most, to spare slurmctld.
        std::this_thread::sleep_for(std::chrono::duration<double>(std::clamp(elapsed / 10.0, 0.5, 10.0)));
    }

    for (const auto& [index, state] : renderStates)
        if (state != "COMPLETED")
            std::cerr << "render task " << renderId << "_" << index << " (" << job.taskFrame(index).out << ", "
                      << describe(job.taskSamples(index)) << ") " << state << ": see " << job.renderLog(renderId, index)
                      << "\n";
    bool allWritten = true;
    for (size_t f = 0; f < job.frames.size(); ++f) {
        const std::string log = job.mergeLog(mergeId, int(f));
        if (mergeStates[int(f)] == "COMPLETED") {
            std::cout << "wrote " << job.frames[f].out << "\n";
        } else {
            allWritten = false;
            std::cerr << "merge task " << mergeId << "_" << f << " " << mergeStates[int(f)] << ": " << lastLine(log)
                      << " (log: " << log << ")\n";
        }
    }
    return allWritten;
}

void runSubmit(const SubmitOptions& o) {
    const SlurmJob job = planJob(o);
    writeJobFiles(job);
    if (o.dryRun) {
        std::cout << "# " << job.renderScriptPath() << "\n"
                  << job.renderScript() << "\n# " << job.mergeScriptPath() << "\n"
                  << job.mergeScript() << "\n# submitted with\n"
                  << shellCommand(job.renderSubmission()) << "\n"
                  << shellCommand(job.mergeSubmission("RENDER_JOB_ID")) << "\n";
        return;
    }
    removeEarlierResults(job);
    const std::string renderId = submit(job.renderSubmission());
    std::string mergeId;
    try {
        mergeId = submit(job.mergeSubmission(renderId));
    } catch (const std::exception&) {
        runProcess({"scancel", renderId});
        std::cerr << "woven submit: cancelled render job " << renderId << ", which nothing would merge\n";
        throw;
    }
    std::cout << "render job " << renderId << ": " << job.renderTasks() << " tasks, logs " << job.logFolder() << "/render_"
              << renderId << "_<task>.log\n"
              << "merge job " << mergeId << ": after every render task, logs " << job.logFolder() << "/merge_" << mergeId
              << "_<frame>.log\n";
    for (const ClusterFrame& f : job.frames) std::cout << "frame " << f.out << " from " << f.scene << "\n";
    std::cout.flush();
    if (o.wait && !waitForJobs(job, renderId, mergeId, o.waitTimeout))
        throw std::runtime_error("not every frame was written (see above)");
}

}  // namespace

void addSubmitCommand(CLI::App& app) {
    auto o = std::make_shared<SubmitOptions>();
    CLI::App* cmd = app.add_subcommand(
        "submit", "Render on a Slurm cluster: a job array of sample ranges, merged exactly (docs/CLUSTER.md)");
    cmd->add_option("scenes", o->scenes,
                    "scene file; with --frames A..B one with a frame number field (scene_%04d.json), or one per frame")
        ->required();
    cmd->add_option("-o,--out", o->out, "merged EXR; with several frames a pattern such as frame_%04d.exr")->required();
    cmd->add_option("--tasks", o->tasks, "render tasks per frame, each a range of the samples")
        ->required()
        ->transform(wholeNumber(1, 1000000));
    cmd->add_option("--frames", o->frames, "A..B: the frame numbers (an animation: SCENE and OUT have a %04d field)");
    cmd->add_option("--job-dir", o->jobDir,
                    "folder of the job's scripts, logs and part files, on a file system every node shares "
                    "(default: OUT's name with .slurm)");
    // The render options, recorded as typed before CLI11's transforms rewrite them (--tone-map's
    // names become numbers), so that every task gets exactly what was given here; except --spp,
    // the frame's samples per pixel, which the tasks split, --noise-threshold, which each task
    // gets for its share (SlurmJob::noiseThreshold), and --denoise, which is the merge's
    // (SlurmJob::denoise).
    for (CLI::Option* option : addRenderOptions(*cmd, o->render)) {
        if (option->check_lname("spp") || option->check_lname("noise-threshold") || option->check_lname("denoise")) continue;
        // A flag is passed on as itself: `woven render` reads "--strict true" as a stray argument.
        const bool flag = option->get_expected_max() == 0;
        option->transform([o, name = option->get_name(), flag](std::string value) {
            if (!flag || CLI::detail::to_flag_value(value) > 0) o->renderArguments.push_back(name);
            if (!flag) o->renderArguments.push_back(value);
            return value;
        });
    }
    cmd->add_option("--partition", o->sbatch.partition, "Slurm partition");
    cmd->add_option("--time", o->sbatch.time, "Slurm time limit of each job, e.g. 30:00 (sbatch --time)");
    cmd->add_option("--cpus-per-task", o->sbatch.cpusPerTask, "CPUs of each render task")->transform(wholeNumber(1));
    cmd->add_option("--sbatch", o->sbatch.extra, "one more sbatch argument, e.g. --sbatch=--account=lab (repeatable)");
    cmd->add_flag("--requeue", o->sbatch.requeue,
                  "let Slurm requeue a task that is pre-empted or loses its node (it renders the same samples again)");
    cmd->add_flag("--wait", o->wait, "wait until the merge is done, showing progress; fail when a frame is not written");
    cmd->add_option("--wait-timeout", o->waitTimeout, "give up waiting after this many seconds (the jobs go on)")
        ->check(positiveNumber());
    cmd->add_flag("--dry-run", o->dryRun, "write the job scripts and print them with the sbatch commands; submit nothing");
    cmd->callback([o] { runSubmit(*o); });
}

}  // namespace woven
