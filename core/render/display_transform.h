#pragma once
// How a frame's linear radiance is shown: exposure, a tone curve and sRGB encoding, for PNG
// output and the previewer's window alike (shaders/display.frag is its GLSL twin).
#include <string>

#include "image.h"

namespace woven {

// Linear radiance to 8-bit display colour: scale by 2^exposure, tone-map, then sRGB-encode.
// PNG output, the previewer's window (and shaders/display.frag) all go through this.
enum class ToneMap {
    Clamp,     // values above 1 clip to white: colours are the reflectances as given
    Reinhard,  // c / (1 + c) per channel
    Aces       // Narkowicz's fit of the ACES filmic curve
};
struct DisplayTransform {
    float exposure = 0.0f;  // in stops
    ToneMap toneMap = ToneMap::Aces;  // what woven shows and writes unless told otherwise
};
glm::u8vec3 displayColor(const glm::vec3& linear, const DisplayTransform& transform);
void writePng(const std::string& path, const Image& image, const DisplayTransform& transform = {});

}  // namespace woven
