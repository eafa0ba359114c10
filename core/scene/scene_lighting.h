#pragma once
// What lights a scene when its file brings no light, as glTF viewers do: a neutral studio
// environment built into woven (a soft grey dome over a light grey floor, a key, a fill and a rim
// soft box); and the command line's --environment, which replaces a scene's environment with an
// image or a uniform grey.
#include <memory>
#include <string>

#include "scene_description.h"

namespace woven {

// Whether the scene brings a light source: a punctual light of non-zero intensity, an
// environment brighter than black, or emissive surfaces that deliver at least kDimIrradiance to
// the scene's centre (emitterIrradiance(): textured emission by its texture's mean), as a lamp does. Fainter emitters do not count: in glTF
// files they are screens, LEDs and signs far more often than the light a scene is seen by.
bool hasLightSources(const SceneDescription& scene);

// The irradiance (W/m^2, luminance) the scene's punctual lights, environment and emitters give a
// surface facing each at the centre of the scene's bounds, unoccluded: a scale for telling a
// scene lit too dimly to see (glTF lights of a few lux or candela, read as the photometric units
// they are).
float lightIrradianceAtCentre(const SceneDescription& scene);

// The part of it from emissive surfaces, by the light they deliver: each material's emission
// factor (with emissive_strength) times the mean of its emissive texture, so a texture that is
// mostly black (a helmet's lamps, a bottle's label) counts for the little it emits; each triangle
// as a small area light, L A cos / d^2 with d^2 at least the triangle's area.
float emitterIrradiance(const SceneDescription& scene, const glm::vec3& at);

// The built-in studio environment (an equirectangular image, 512 x 256), of mean radiance 1
// over the sphere: on average as bright as `--environment 1`.
Environment studioEnvironment();

// Why a scene was given the studio environment, as glTF viewers light a file with theirs: it
// brings no light source, or its lights and environment are too dim to see at exposure 0 (glTF's
// photometric units read as they are: a 3 lux sun gives 0.004 W/m^2).
enum class DefaultLighting { None, NoLight, TooDim };

// Irradiance (W/m^2) below which a scene counts as too dim: half what a uniform environment of
// radiance 1 gives (pi), and about a quarter of what the studio gives a surface facing up. glTF viewers add their
// environment to a file's own lights, so a file its own lights give less is darker at the
// defaults than any viewer shows it.
inline constexpr float kDimIrradiance = 1.5f;

// Adds studioEnvironment() to a scene that has no light source or is too dim, in place of its
// environment and beside its punctual lights, unless a woven scene file chose its lighting;
// returns why it did (None: it did not).
DefaultLighting lightByDefault(SceneDescription& scene);

// An equirectangular environment image (readImage(), .png/.jpg decoded from sRGB), its pixels
// checked as light: a non-finite or too bright one (light_limits.h) throws ImageError naming
// the file and the pixel; negative ones, which resampling filters leave in HDR files, become 0
// with one warning on stderr.
std::shared_ptr<Image> readEnvironmentImage(const std::string& path);

// --environment's value: an image file (.hdr, .exr; .png/.jpg decoded from sRGB), a number,
// the radiance of a uniform grey environment, or "none" (black, and no default lighting). Throws SceneError naming the option and the file.
Environment environmentFromOption(const std::string& value);

}  // namespace woven
