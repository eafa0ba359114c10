#pragma once
// PNG through libpng, which inflates a file's image data row by row into rows of the size its
// header claims, so memory follows the image's size (checked first) and not the data's:
// stb_image inflated into a buffer it doubled as it went, and a 783 KB PNG of one pixel took
// 770 MB. The values are libpng's as OpenImageIO, which woven read PNG through before, had them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace woven {

// Grey, grey + alpha, RGB or RGBA (1 to 4 channels), interleaved from the top row; palettes,
// grey below 8 bits and transparency chunks expanded; 16-bit files as 16-bit values.
struct PngPixels {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> bytes;  // 8-bit files
    std::vector<uint16_t> words;       // 16-bit files
};

// Throws ImageError naming `name` for an image over the limits (checked from its header, before
// anything is decoded) and for anything libpng refuses.
PngPixels decodePng(const unsigned char* data, size_t size, const std::string& name);

}  // namespace woven
