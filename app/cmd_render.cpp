// `woven render SCENE`: a final frame of a scene file with either integrator, to EXR or PNG.
#include <csignal>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

#include "commands.h"
#include "image_io.h"
#include "make_woven.h"
#include "progress_bar.h"
#include "render_job.h"
#include "scene_loader.h"
#include "woven_params_json.h"

namespace woven {

namespace {

struct RenderOptions {
    std::string scene, out;
    int spp = 0;
    double time = 0.0;
    std::string integrator;
    int width = 0, height = 0;
    uint64_t seed = 0;
    int threads = 0;
    int maxDepth = 8;
    int firstSample = 0;
    std::vector<std::string> woven;
};

// Set by SIGINT; the render stops after its current pass. The handler resets itself, so a second
// Ctrl-C ends the process at once.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");
extern "C" void onInterrupt(int) { interrupted.store(true); }

class InterruptGuard {
public:
    InterruptGuard() {
        interrupted.store(false);
        struct sigaction action {};
        action.sa_handler = onInterrupt;
        action.sa_flags = SA_RESETHAND;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_);
    }
    ~InterruptGuard() { sigaction(SIGINT, &previous_, nullptr); }

private:
    struct sigaction previous_ {};
};

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

// "out.exr" -> "out.partial.exr": an interrupted render never takes the final name.
std::string partialName(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

// --woven NAME=JSON: material NAME ("*": every material) becomes woven with these parameters,
// on top of the woven parameters it already has.
void applyWovenOption(SceneDescription& scene, const std::string& option) {
    const size_t eq = option.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SceneError(scene.source + ": --woven '" + option + "': expected NAME=JSON, e.g. cloth='{\"ex\":100}'");
    const std::string name = option.substr(0, eq);
    const std::string where = scene.source + ": --woven " + name;
    const Material& first = scene.materials[size_t(selectMaterials(scene, name).front())];
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(option.substr(eq + 1));
    } catch (const std::exception& e) {
        throw SceneError(where + ": not valid JSON: " + e.what());
    }
    WovenParams params;
    try {
        params = paramsFromJson(j, first.woven.value_or(WovenParams{}));
    } catch (const std::exception& e) {
        throw SceneError(where + ": " + e.what());
    }
    makeWoven(scene, name, params);
}

void writeFilm(const std::string& path, const FilmImage& film) {
    if (lowerExtension(path) == ".exr") {
        writeExr(path, ExrImage{film.radiance, film.sampleCount}, ExrPrecision::Float);
    } else {
        PngOptions options;
        options.toneMap = ToneMap::Aces;
        writePng(path, film.radiance, options);
    }
}

std::string formatSeconds(double seconds) {
    std::ostringstream s;
    s.precision(3);
    s << seconds << " s";
    if (seconds >= 60.0) s << " (" << formatDuration(seconds) << ")";
    return s.str();
}

std::string progressStatus(const RenderProgress& p, bool timeLimited) {
    std::ostringstream s;
    s << p.samplesDone;
    if (!timeLimited) s << "/" << p.samplesTotal;
    s << " spp  " << formatCount(p.samplesPerSecond) << " samples/s  " << formatCount(p.raysPerSecond)
      << " rays/s  elapsed " << formatDuration(p.elapsed) << "  left " << formatDuration(p.remaining);
    return s.str();
}

int runRender(RenderOptions o) {
    if (o.out.empty()) o.out = std::filesystem::path(o.scene).stem().string() + ".exr";
    const std::string extension = lowerExtension(o.out);
    if (extension != ".exr" && extension != ".png")
        throw std::invalid_argument("--out '" + o.out + "': unknown image type (expected .exr or .png)");

    auto scene = std::make_shared<SceneDescription>(loadScene(o.scene));
    for (const std::string& option : o.woven) applyWovenOption(*scene, option);

    RenderSettings settings;
    settings.width = o.width > 0 ? o.width : scene->render.width > 0 ? scene->render.width : 640;
    settings.height = o.height > 0 ? o.height : scene->render.height > 0 ? scene->render.height : 480;
    const bool timeLimited = o.time > 0.0;
    if (o.spp > 0) settings.spp = o.spp;
    else if (timeLimited) settings.spp = std::numeric_limits<int>::max() - o.firstSample;
    else settings.spp = scene->render.spp > 0 ? scene->render.spp : 64;
    settings.timeLimit = o.time;
    settings.integrator = !o.integrator.empty() ? o.integrator : !scene->render.integrator.empty() ? scene->render.integrator : "auto";
    settings.seed = o.seed;
    settings.threads = o.threads;
    settings.maxDepth = o.maxDepth;
    settings.firstSample = o.firstSample;

    RenderJob job(scene, settings);
    RenderProgress last;
    {
        InterruptGuard guard;
        ProgressBar bar("render");
        if (settings.integrator == "auto") std::cerr << "render: choosing the integrator (a short pilot of each)\n";
        job.run(interrupted, [&](const RenderProgress& p) {
            last = p;
            const double fraction = timeLimited && o.spp <= 0 ? p.elapsed / o.time : double(p.samplesDone) / p.samplesTotal;
            bar.update(fraction, progressStatus(p, timeLimited && o.spp <= 0));
        });
        bar.finish();
    }
    const bool wasInterrupted = interrupted.load();
    if (last.samplesDone == 0) {
        std::cerr << "woven render: interrupted before the first pass finished; nothing written\n";
        return wasInterrupted ? 130 : 1;
    }
    const std::string path = wasInterrupted ? partialName(o.out) : o.out;
    writeFilm(path, job.snapshot());
    std::cerr << (wasInterrupted ? "interrupted: wrote " : "wrote ") << path << "\n";
    std::cout << "integrator " << job.integratorName() << ", " << last.samplesDone << " spp, " << settings.width << "x"
              << settings.height << ", " << formatSeconds(last.elapsed) << ", "
              << formatCount(last.samplesPerSecond) << " samples/s, " << formatCount(last.raysPerSecond) << " rays/s\n";
    return wasInterrupted ? 130 : 0;
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a final frame of a scene (.gltf, .glb or a woven .json scene file)");
    cmd->add_option("scene", o->scene, "scene file")->required();
    cmd->add_option("--spp", o->spp, "samples per pixel (default: the scene's, else 64; with --time: no limit)")
        ->check(CLI::Range(1, 1 << 24));
    cmd->add_option("--time", o->time, "render for this many seconds (stops after the pass that crosses it)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--integrator", o->integrator, "bdpt, path or auto (default: the scene's, else auto)")
        ->check(CLI::IsMember({"bdpt", "path", "auto"}));
    cmd->add_option("--width", o->width, "image width (default: the scene's, else 640)")->check(CLI::Range(1, 1 << 15));
    cmd->add_option("--height", o->height, "image height (default: the scene's, else 480)")->check(CLI::Range(1, 1 << 15));
    cmd->add_option("-o,--out", o->out,
                    "output image: .exr (linear float RGB + sample count N) or .png (sRGB, tone-mapped); "
                    "default: the scene's name with .exr");
    cmd->add_option("--seed", o->seed, "random seed");
    cmd->add_option("--threads", o->threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-depth", o->maxDepth, "maximum bounces")->check(CLI::Range(1, 1000));
    cmd->add_option("--first-sample", o->firstSample,
                    "index of the first sample (disjoint ranges, e.g. from a job array, merge by sample count)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--woven", o->woven, "NAME=JSON: make material NAME woven with these parameters (repeatable)");
    cmd->callback([o] {
        if (int rc = runRender(*o)) throw CLI::RuntimeError(rc);
    });
}

}  // namespace woven
