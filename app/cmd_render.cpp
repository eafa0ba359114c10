// `woven render SCENE`: a final frame of a scene file with either integrator, to EXR or PNG.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "commands.h"
#include "fabric_scene.h"
#include "number_checks.h"
#include "frame_limits.h"
#include "frame_denoise.h"
#include "frame_io.h"
#include "image_io.h"
#include "integrators.h"
#include "interrupt_guard.h"
#include "output_path.h"
#include "progress_bar.h"
#include "render_options.h"
#include "render_job.h"
#include "scene_camera.h"
#include "scene_lighting.h"
#include "scene_loader.h"

namespace woven {

namespace {

struct RenderCommand {
    std::string scene, out;
    RenderOptions options;
    double time = 0.0;
    int64_t firstSample = 0;
    bool list = false;
};

std::string formatSeconds(double seconds) {
    std::ostringstream s;
    s.precision(3);
    s << seconds << " s";
    if (seconds >= 60.0) s << " (" << formatDuration(seconds) << ")";
    return s.str();
}

// "23.4": the mean samples per pixel.
std::string formatMean(const std::vector<float>& sampleCount) {
    double sum = 0.0;
    for (float n : sampleCount) sum += n;
    std::ostringstream s;
    s.precision(3);
    s << sum / double(std::max<size_t>(sampleCount.size(), 1));
    return s.str();
}

std::string progressStatus(const RenderProgress& p, bool timeLimited, bool adaptive) {
    std::ostringstream s;
    s << p.samplesDone;
    if (!timeLimited) s << "/" << p.samplesTotal;
    s << " spp  ";
    if (adaptive) s << int(std::ceil(100.0 * p.activeFraction)) << "% of pixels sampling  ";
    s << formatCount(p.samplesPerSecond) << " samples/s  " << formatCount(p.raysPerSecond)
      << " rays/s  elapsed " << formatDuration(p.elapsed) << "  left " << formatDuration(p.remaining);
    return s.str();
}

// --list: what --camera, --woven and the rest can name, as the file has it.
void listScene(const SceneDescription& scene, std::ostream& out) {
    const auto quoted = [](const std::string& s) { return "'" + s + "'"; };
    out << "cameras:" << (scene.cameras.empty() ? " none (--camera auto frames the scene)" : "") << "\n";
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        out << "  " << i << "  " << quoted(scene.cameras[i].name) << "  node " << quoted(scene.cameras[i].node) << "\n";
    out << "materials:" << (scene.materials.empty() ? " none" : "") << "\n";
    for (const Material& m : scene.materials)
        out << "  " << quoted(m.name) << "  " << (m.woven ? "woven" : "glTF") << "\n";
    out << "meshes:" << (scene.meshes.empty() ? " none" : "") << "\n";
    bool emitters = false;
    for (const Mesh& m : scene.meshes) {
        const bool hasMaterial = m.material >= 0 && m.material < int(scene.materials.size());
        const bool emits = hasMaterial && scene.materials[size_t(m.material)].emits();
        emitters = emitters || emits;
        out << "  " << quoted(m.name) << "  " << m.triangles.size() << " triangles"
            << (m.instances ? " x " + std::to_string(m.instances->size()) + " instances" : "") << "  material "
            << (hasMaterial ? quoted(scene.materials[size_t(m.material)].name) : "default")
            << (emits ? "  emissive" : "") << "\n";
    }
    // Emissive meshes light a scene by what they deliver (scene_lighting.h): a lamp does, a
    // screen or a mostly black emissive texture does not.
    out << "lights:" << (scene.lights.empty() ? (emitters ? " none but the emissive meshes" : " none") : "") << "\n";
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const PunctualLight& l = scene.lights[i];
        const bool directional = l.type == PunctualLight::Type::Directional;
        out << "  " << (directional ? "directional" : l.type == PunctualLight::Type::Spot ? "spot" : "point") << "  "
            << quoted(l.name.empty() ? "light" + std::to_string(i) : l.name) << "  intensity " << l.intensity.r << " "
            << l.intensity.g << " " << l.intensity.b << (directional ? " W/m^2" : " W/sr") << "\n";
    }
    if (emitters) {
        const float E = emitterIrradiance(scene, sceneBounds(scene).centre());
        out << "  emissive meshes: about " << E << " W/m^2 at the scene's centre ("
            << (E >= kDimIrradiance ? "they light it" : "too little to light it") << ")\n";
    }
}

int runRender(RenderCommand o) {
    if (o.list) {
        listScene(loadSceneOrFabric(o.scene, o.options.frame.load), std::cout);
        return 0;
    }
    if (o.out.empty()) o.out = std::filesystem::path(o.scene).stem().string() + ".exr";
    checkFrameFileName(o.out);

    auto scene = std::make_shared<SceneDescription>(loadSceneOrFabric(o.scene, o.options.frame.load));
    if (scene->photo)
        std::cerr << "render: " << o.scene << " is a shot: its photo " << scene->photo->image
                  << " is for woven fit; the render does not use it\n";
    applySceneOptions(*scene, o.options.frame);
    // Now that every input is read (the environment image too), none may be an output.
    checkOutput(o.out);
    checkOutput(partialName(o.out));

    RenderSettings settings = frameSettings(*scene, o.options.frame);
    const bool timeLimited = o.time > 0.0;
    const bool sppGiven = o.options.frame.spp > 0;
    if (timeLimited && !sppGiven)
        settings.spp = int(std::min<int64_t>(std::numeric_limits<int>::max(), kSampleIndexLimit - o.firstSample));
    settings.timeLimit = o.time;
    settings.threads = o.options.threads;
    if (settings.threads > workerThreads(settings.threads))
        std::cerr << "warning: --threads " << settings.threads << ": this machine has " << workerThreads(0)
                  << " hardware threads for woven; using " << workerThreads(0) << "\n";
    if (!withinSampleIndexLimit(o.firstSample, settings.spp))
        throw std::invalid_argument("--first-sample " + std::to_string(o.firstSample) + " with --spp " +
                                    std::to_string(settings.spp) + " ends past sample index 2^62 (" +
                                    std::to_string(kSampleIndexLimit) + "), where the integrator pilot's samples are");
    settings.firstSample = o.firstSample;

    RenderJob job(scene, settings);
    RenderProgress last;
    {
        InterruptGuard guard;
        ProgressBar bar("render");
        if (settings.integrator == autoIntegrator().name) std::cerr << "render: choosing the integrator (a short pilot of each)\n";
        job.run(interrupted(), [&](const RenderProgress& p) {
            last = p;
            const double fraction = p.activeFraction == 0.0           ? 1.0  // every pixel below the noise threshold
                                    : timeLimited && !sppGiven ? p.elapsed / o.time
                                                               : double(p.samplesDone) / p.samplesTotal;
            bar.update(fraction, progressStatus(p, timeLimited && !sppGiven, settings.noiseThreshold > 0.0));
        });
        bar.finish();
    }
    const bool wasInterrupted = interrupted().load();
    if (last.samplesDone == 0) {
        std::cerr << "woven render: interrupted before the first pass finished; nothing written\n";
        return wasInterrupted ? 130 : 1;
    }
    const std::string path = wasInterrupted ? partialName(o.out) : o.out;
    FilmImage film = job.snapshot();
    // An interrupted frame is written at once, as rendered: it is for looking at or merging.
    if (o.options.frame.denoise && !wasInterrupted) denoiseFilm(film);
    writeFrame(path, film.exr(), o.options.frame.display);
    std::cerr << (wasInterrupted ? "interrupted: wrote " : "wrote ") << path << "\n";
    std::cout << "integrator " << job.integratorName() << ", " << last.samplesDone << " spp";
    if (settings.noiseThreshold > 0.0)
        std::cout << " at most (" << formatMean(film.sampleCount) << " on average, noise threshold " << settings.noiseThreshold << ")";
    std::cout << ", " << settings.width << "x"
              << settings.height << ", " << formatSeconds(last.elapsed) << ", "
              << formatCount(last.samplesPerSecond) << " samples/s, " << formatCount(last.raysPerSecond) << " rays/s\n";
    return wasInterrupted ? 130 : 0;
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderCommand>();
    CLI::App* cmd = app.add_subcommand("render", "Render a final frame of a scene (.gltf, .glb or a woven .json scene file)");
    cmd->add_option("scene", o->scene, "scene file (.gltf, .glb, .json), or a fabric on woven's drape: a library fabric's name, a fabric or material .json, a .wif draft or a .u3ma/.u3m")->required();
    addRenderOptions(*cmd, o->options);
    cmd->add_option("--time", o->time, "render for this many seconds (stops after the pass that crosses it; "
                                       "without --spp no sample limit)")
        ->check(positiveNumber());
    cmd->add_option("-o,--out", o->out,
                    "output image: .exr (linear float RGB, sample count N, and the exact sample sums and range "
                    "that woven merge adds up) or .png (sRGB, tone-mapped); default: the scene's name with .exr");
    cmd->add_option("--first-sample", o->firstSample,
                    "index of the first sample (disjoint ranges, e.g. from a job array, merge by sample count)")
        ->transform(wholeNumber(0, kSampleIndexLimit - 1));
    CLI::Option* list = cmd->add_flag("--list", o->list,
                                      "print the scene's cameras (the numbers --camera takes), materials, meshes and "
                                      "lights, and render nothing");
    cmd->callback([o, cmd, list] {
        // --list reads the scene and renders nothing: any option but those of the reading
        // (--allow-any-path, --strict) would be ignored without a word (`--list -o x.exr` wrote nothing).
        for (const CLI::Option* option : cmd->get_options())
            if (o->list && option != list && option->count() > 0 && option->nonpositional() &&
                !option->check_lname("allow-any-path") && !option->check_lname("strict"))
                throw CLI::ExcludesError(option->get_name(), list->get_name());
        if (int rc = runRender(*o)) throw CLI::RuntimeError(rc);
    });
}

}  // namespace woven
