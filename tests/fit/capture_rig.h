#pragma once
// The synthetic capture rig of the fit's round trips (docs/FIT.md, "The rig"): a flat square
// swatch, the camera straight above it, a point light beside the camera, as a phone with its
// flash sees a swatch on a table. writeCaptureShot() writes the glTF file (core's glTF writer),
// the shot file, and the "photo": woven's own render of a known material, with the sensor's
// noise, the lens's vignette and an exposure applied as the options say, as an sRGB PNG.
#include <cstdint>
#include <string>

#include "woven_params.h"

namespace woven::test {

constexpr float kSwatchMetres = 0.04f;  // 4 cm; one UV unit a metre (flat_cloth.h)

struct RigPhoto {
    WovenParams truth;           // repeat: threads per metre, as one UV unit is a metre
    int size = 128;              // pixels, square
    int height = 0;              // > 0: the photo is `size` wide and this tall (the lens's 13 degrees are its height's)
    int spp = 32;                // the photo's samples: far more than the fit's
    uint64_t seed = 1234;        // not the fit's seed
    float noise = 0.0f;          // sensor noise: Gaussian, this fraction of each value
    float vignetteSigmaPx = 0;   // applied to the photo; the shot says it
    float exposure = 1.0f;       // applied to the photo
    bool exposureKnown = true;   // true: the shot says it; false: "free"
    // The point light: by default the "flash", 5 mm beside the lens, along +x. Below the swatch
    // (y < 0) it lights it from behind, as the backlit photo is taken.
    glm::vec3 light{0.005f, 0.15f, 0.0f};
    float lightIntensity = 0.08f;  // W/sr
    // The cloth in the photo turned by this many degrees about the swatch's centre, as a swatch
    // laid a little askew: the shot's mesh stays along the camera's axes.
    float turnDegrees = 0.0f;
};

// The shot file's path (DIR/NAME.json beside DIR/NAME.png and DIR/swatch.gltf).
std::string writeCaptureShot(const std::string& dir, const std::string& name, const RigPhoto& photo);

// The same shot file with its photo key replaced by `photoJson` (a JSON object, or "" for none);
// `height` > 0: the frame `size` wide and `height` tall.
std::string writeShotFile(const std::string& dir, const std::string& name, int size, const std::string& photoJson,
                          const glm::vec3& light = RigPhoto{}.light, float lightIntensity = RigPhoto{}.lightIntensity,
                          int height = 0);

}  // namespace woven::test
