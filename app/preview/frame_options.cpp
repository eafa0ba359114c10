#include "frame_options.h"

#include <iostream>
#include <map>

#include "make_woven.h"
#include "scene_lighting.h"
#include "scene_validation.h"

namespace woven {

void addFrameOptions(CLI::App& command, FrameOptions& o) {
    command.add_option("--width", o.width, "image width (default: the scene's, else 640)")->check(CLI::Range(1, 1 << 15));
    command.add_option("--height", o.height, "image height (default: the scene's, else 480)")->check(CLI::Range(1, 1 << 15));
    command.add_option("--spp", o.spp, "samples per pixel (default: the scene's, else 64)")->check(CLI::Range(1, 1 << 24));
    command.add_option("--integrator", o.integrator, "bdpt, path or auto (default: the scene's, else auto)")
        ->check(CLI::IsMember(std::vector<std::string>(std::begin(kIntegratorNames), std::end(kIntegratorNames))));
    command.add_option("--seed", o.seed, "random seed");
    command.add_option("--max-depth", o.maxDepth, "maximum bounces")->check(CLI::Range(1, 1000));
    command.add_option("--woven", o.woven, "NAME=JSON: make material NAME woven with these parameters (repeatable)");
    command.add_option("--environment", o.environment,
                       "light the scene by an equirectangular image (.hdr, .exr, .png, .jpg) or a uniform grey "
                       "radiance (a number), instead of its own environment")
        ->type_name("FILE|GREY");
    static const std::map<std::string, ToneMap> toneMaps = {
        {"clamp", ToneMap::Clamp}, {"reinhard", ToneMap::Reinhard}, {"aces", ToneMap::Aces}};
    command.add_option("--exposure", o.display.exposure, "PNG and display exposure in stops");
    command.add_option("--tone-map", o.display.toneMap, "PNG and display tone curve: aces (default), clamp or reinhard")
        ->transform(CLI::CheckedTransformer(toneMaps, CLI::ignore_case).description(""))
        ->type_name("aces|clamp|reinhard");
}

void applySceneOptions(SceneDescription& scene, const FrameOptions& options) {
    validateScene(scene);
    if (!options.environment.empty()) scene.environment = environmentFromOption(options.environment);
    for (const std::string& option : options.woven) applyWovenOption(scene, option);
    // An --environment given is the user's choice, even a black one.
    if (options.environment.empty() && lightByDefault(scene))
        std::cerr << "note: " << scene.source
                  << " has no light source (punctual light or environment): lit by woven's studio environment "
                     "(--environment FILE|GREY to choose)\n";
}

RenderSettings frameSettings(const SceneDescription& scene, const FrameOptions& o) {
    RenderSettings settings = defaultRenderSettings(scene);
    if (o.width > 0) settings.width = o.width;
    if (o.height > 0) settings.height = o.height;
    if (o.spp > 0) settings.spp = o.spp;
    if (!o.integrator.empty()) settings.integrator = o.integrator;
    settings.seed = o.seed;
    settings.maxDepth = o.maxDepth;
    return settings;
}

}  // namespace woven
