#include "frame_options.h"

#include <map>

#include "make_woven.h"

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
    static const std::map<std::string, ToneMap> toneMaps = {
        {"clamp", ToneMap::Clamp}, {"reinhard", ToneMap::Reinhard}, {"aces", ToneMap::Aces}};
    command.add_option("--exposure", o.display.exposure, "PNG and display exposure in stops");
    command.add_option("--tone-map", o.display.toneMap, "PNG and display tone curve: aces (default), clamp or reinhard")
        ->transform(CLI::CheckedTransformer(toneMaps, CLI::ignore_case).description(""))
        ->type_name("aces|clamp|reinhard");
}

void applyWovenOptions(SceneDescription& scene, const FrameOptions& options) {
    for (const std::string& option : options.woven) applyWovenOption(scene, option);
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
