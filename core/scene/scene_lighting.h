#pragma once
// What lights a scene when its file brings no light, as glTF viewers do: a neutral studio
// environment built into woven (a soft grey dome over a darker floor, a key, a fill and a rim
// soft box); and the command line's --environment, which replaces a scene's environment with an
// image or a uniform grey.
#include <memory>
#include <string>

#include "scene_description.h"

namespace woven {

// Whether the scene brings a light source: a punctual light of non-zero intensity or an
// environment brighter than black. Emissive materials do not count: in glTF files they are
// screens, LEDs and signs far more often than the light a scene is meant to be seen by.
bool hasLightSources(const SceneDescription& scene);

// The irradiance (W/m^2, luminance) the scene's punctual lights and environment give a surface
// facing each at the centre of the scene's bounds, unoccluded: a scale for telling a scene lit
// too dimly to see (glTF lights of a few lux or candela, read as the photometric units they are).
float punctualAndEnvironmentIrradiance(const SceneDescription& scene);

// The built-in studio environment (an equirectangular image, 512 x 256).
Environment studioEnvironment();

// Lights a scene without light sources with studioEnvironment(), unless a woven scene file set
// its lighting; returns whether it did.
bool lightByDefault(SceneDescription& scene);

// An equirectangular environment image (readImage(), .png/.jpg decoded from sRGB), its pixels
// checked as light: a non-finite or too bright one (light_limits.h) throws ImageError naming
// the file and the pixel; negative ones, which resampling filters leave in HDR files, become 0
// with one warning on stderr.
std::shared_ptr<Image> readEnvironmentImage(const std::string& path);

// --environment's value: an image file (.hdr, .exr; .png/.jpg decoded from sRGB) or a number,
// the radiance of a uniform grey environment. Throws SceneError naming the option and the file.
Environment environmentFromOption(const std::string& value);

}  // namespace woven
