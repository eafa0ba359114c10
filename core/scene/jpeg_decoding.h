#pragma once
// JPEG through libjpeg-turbo, as woven decoded JPEG before (through OpenImageIO, which used it
// with the same settings), so that photos (woven fit's) and textures decode to the same values;
// stb_image's decoder differs by up to 2 of 255 levels.
#include <cstddef>
#include <string>
#include <vector>

namespace woven {

// Grey (1 channel) or RGB (3), 8 bits, interleaved from the top row; CMYK files as RGB.
struct JpegPixels {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> bytes;
};

// Throws ImageError naming `name` for an image over the limits (checked from its header, before
// anything is decoded) and for anything libjpeg refuses.
JpegPixels decodeJpeg(const unsigned char* data, size_t size, const std::string& name);

}  // namespace woven
