#include "frame_options.h"

#include <cctype>
#include <iostream>
#include <map>
#include <sstream>

#include "choice_check.h"
#include "integrators.h"
#include "number_checks.h"
#include "scene_camera.h"
#include "woven_assignment.h"
#include "light_limits.h"
#include "scene_lighting.h"
#include "scene_validation.h"
#include "studio_environments.h"
#include "display_transform.h"

namespace woven {

void addFrameOptions(CLI::App& command, FrameOptions& o) {
    command.add_option("--width", o.width, "image width (default: the scene's, else 640)")->transform(wholeNumber(1, 1 << 15));
    command.add_option("--height", o.height, "image height (default: the scene's, else 480)")->transform(wholeNumber(1, 1 << 15));
    command.add_option("--spp", o.spp, "samples per pixel (default: the scene's, else 64)")->transform(wholeNumber(1, 1 << 24));
    std::string integrators;
    for (const IntegratorKind& kind : integratorKinds())
        integrators += std::string(integrators.empty() ? "" : "; ") + kind.name + ": " + kind.description;
    command.add_option("--integrator", o.integrator,
                       integrators + " (default: the scene's, else " + autoIntegrator().name + ")")
        ->check(oneOf(integratorNames()));
    command.add_option("--seed", o.seed, "random seed")->transform(wholeNumber(0));
    command.add_option("--sampler", o.sampler,
                       "sobol (Owen-scrambled Sobol points, converging faster) or independent (PCG numbers, as woven "
                       "rendered before; default: the scene's, else sobol)")
        ->check(oneOf(std::vector<std::string>(std::begin(kSamplerNames), std::end(kSamplerNames))));
    command.add_option("--max-depth", o.maxDepth, "maximum bounces")->transform(wholeNumber(1, 1000));
    std::ostringstream threshold;
    threshold << "adaptive sampling: a pixel stops once the estimated relative error of its mean is below this, "
                 "--spp is then its most; 0: every pixel takes every sample (default: "
              << kDefaultNoiseThreshold << ")";
    command.add_option("--noise-threshold", o.noiseThreshold, threshold.str())->check(finiteNumber(0.0));
    command.add_flag("--filter", o.filterRender,
                     "experimental: the final render filters woven materials over each pixel's footprint, blending "
                     "to the weave's far field (biased by about 2 % per pixel and slower: docs/RESULTS.md)");
    CLI::Option* denoise = command.add_flag(
        "--denoise,!--no-denoise", o.denoise,
        "denoise the final frame, guided by its albedo, normal, depth and direct-light passes (the EXR keeps the "
        "noisy beauty as noisy.R/G/B; default: on; --no-denoise: the beauty as rendered)");
    command.add_flag("!--no-passes", o.passes,
                     "the frame keeps the beauty alone, without the render passes (albedo, normal, depth, direct light) "
                     "that guide the denoiser, so it is not denoised: less work a sample where paths are short "
                     "(docs/RESULTS.md)");
    // --no-passes takes the denoiser's guides away, so it takes the denoiser with it; asked for
    // both, the user hears which to drop rather than getting an undenoised frame.
    command.parse_complete_callback([&o, denoise] {
        if (o.passes) return;
        if (o.denoise && denoise->count() > 0)
            throw CLI::ValidationError("--no-passes", "the denoiser needs the render passes: give --no-denoise, or drop --no-passes");
        o.denoise = false;
    });
    command.add_flag("--allow-any-path", o.load.anyPath,
                     "let a glTF file's buffers and images come from anywhere, not only from its own folder");
    command.add_flag("--strict", o.load.strict,
                     "a texture whose image file is missing is an error (by default: a warning, drawn without it)");
    command.add_option("--camera", o.camera,
                       "the glTF camera to look through: its index (woven render --list), its name or its node's "
                       "name; auto: frame the scene's bounds as for a scene without a camera (default: the first)")
        ->type_name("N|NAME|auto");
    command.add_option("--woven", o.woven, "TARGET=JSON: make the parts TARGET names woven with these parameters: a material name, mesh:NAME, node:NAME, a glob, or * (repeatable; docs/SCENE_FORMAT.md)");
    command.add_option("--environment", o.environment,
                       "light the scene by an equirectangular image (.hdr, .exr, .png, .jpg), a uniform grey "
                       "radiance (a number) or an environment woven generates (" + studioEnvironmentNames() +
                       "), instead of its own environment; none: no environment, and no studio light added "
                       "to a scene whose lights are missing or too dim")
        ->type_name("FILE|GREY|NAME|none");
    command.add_option("--environment-rotation", o.environmentRotation,
                       "turn the environment this many degrees about +y (replaces the scene's environment.rotation)")
        ->check(finiteNumber(-3600.0, 3600.0));
    command.add_option("--environment-intensity", o.environmentIntensity,
                       "scale the environment's radiance, keeping its tint (default 1)")
        ->check(finiteNumber(0.0, 1e6));
    // A validator of our own: CLI11's transformer names its internals ("Check filmic value in
    // {aces->2,...} FAILED") where a user needs the choices.
    const CLI::Validator toneMapNames(
        [](std::string& value) {
            static const std::map<std::string, ToneMap> toneMaps = {
                {"clamp", ToneMap::Clamp}, {"reinhard", ToneMap::Reinhard}, {"aces", ToneMap::Aces}};
            std::string lower = value;
            for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
            const auto found = toneMaps.find(lower);
            if (found == toneMaps.end()) return "'" + value + "' is not a tone curve woven has: aces, clamp or reinhard";
            value = std::to_string(int(found->second));
            return std::string();
        },
        "");
    // 2^40 either way takes any radiance to the display's range; beyond, the scale overflows.
    command.add_option("--exposure", o.display.exposure, "PNG and display exposure in stops")->check(finiteNumber(-40.0, 40.0));
    command.add_option("--tone-map", o.display.toneMap, "PNG and display tone curve: aces (default), clamp or reinhard")
        ->transform(toneMapNames)
        ->type_name("aces|clamp|reinhard");
}

namespace {

// The studio environment for a scene that has no light or too little to see (lightByDefault()),
// said on stderr.
void addDefaultLight(SceneDescription& scene) {
    const float E = lightIrradianceAtCentre(scene);
    switch (lightByDefault(scene)) {
        case DefaultLighting::None: break;
        case DefaultLighting::NoLight:
            std::cerr << "note: " << scene.source
                      << " has no light source (punctual light, environment, or emitters bright enough to light it): lit by woven's "
                         "studio environment (--environment FILE|GREY|none to choose)\n";
            break;
        case DefaultLighting::TooDim:
            std::cerr << "note: " << scene.source << " is lit too dimly to see (about " << E << " W/m^2, " << E * 683.0f
                      << " lux, at its centre): woven's studio environment added beside its lights, as glTF viewers "
                         "do (--environment none for its own lights alone, or --exposure)\n";
            break;
    }
}

}  // namespace

void applySceneOptions(SceneDescription& scene, const FrameOptions& options) {
    if (!options.camera.empty()) chooseCamera(scene, options.camera);
    validateScene(scene);
    if (!options.environment.empty()) scene.environment = environmentFromOption(options.environment);
    // One call, so the options layer by specificity and then in the order given.
    std::vector<WovenAssignment> assignments;
    for (const std::string& option : options.woven) assignments.push_back(parseWovenOption(scene, option));
    if (!assignments.empty()) assignWoven(scene, assignments);
    // An --environment given is the user's choice, even a black one.
    if (options.environment.empty()) addDefaultLight(scene);
    if (options.environmentRotation) scene.environment.rotation = glm::radians(*options.environmentRotation);
    scene.environment.color *= options.environmentIntensity;
    if (const std::string problem = lightValueProblem(scene.environment.color); !problem.empty())
        throw SceneError("--environment-intensity: times the environment's colour " + problem);
}

RenderSettings frameSettings(const SceneDescription& scene, const FrameOptions& o) {
    RenderSettings settings = defaultRenderSettings(scene);
    if (o.width > 0) settings.width = o.width;
    if (o.height > 0) settings.height = o.height;
    if (o.spp > 0) settings.spp = o.spp;
    if (!o.integrator.empty()) settings.integrator = o.integrator;
    settings.seed = o.seed;
    if (!o.sampler.empty()) settings.sampler = samplerKind(o.sampler);
    settings.maxDepth = o.maxDepth;
    if (o.noiseThreshold) settings.noiseThreshold = *o.noiseThreshold;
    settings.filterWeave = o.filterRender;
    settings.renderPasses = o.passes;
    return settings;
}

}  // namespace woven
