#pragma once
// An OpenEXR image as woven reads and writes it, through the OpenEXR library: the first part's
// pixels, every channel in its own type, and its int and string attributes, where woven keeps a
// frame's sample range and identity (frame_io.h). Reading checks the headers (exr_header.h) and
// the image's size (image_checks.h) before OpenEXR allocates anything.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace woven {

enum class ExrChannelType { Half, Float, Uint };

// One channel, one value per pixel, row by row from the top of the data window.
struct ExrChannel {
    std::string name;
    ExrChannelType type = ExrChannelType::Float;
    std::vector<float> values;    // half and float channels (a half is exactly a float)
    std::vector<uint32_t> words;  // 32-bit unsigned channels
};

// An attribute of a type other than int and string: woven reads none, but names its type when
// it finds one where it expects its own.
struct ExrOtherAttribute {
    std::string type;
};
using ExrAttribute = std::variant<int, std::string, ExrOtherAttribute>;

struct ExrFile {
    int width = 0, height = 0;
    std::vector<ExrChannel> channels;                // read: in the file's order (by name)
    std::map<std::string, ExrAttribute> attributes;  // read: all of the header's, OpenEXR's own too

    const ExrChannel* channel(const std::string& name) const;
};

// Throws ImageError naming `name` for bytes that are not a flat (not deep) OpenEXR image within
// woven's limits, or that OpenEXR cannot decode.
ExrFile readExrFile(const unsigned char* data, size_t size, const std::string& name);

// Writes one RLE-compressed scanline part (channels half, float or 32-bit unsigned; attributes
// int or string), atomically (atomic_file.h). Throws ImageError or FileWriteError naming `path`.
void writeExrFile(const std::string& path, const ExrFile& file);

}  // namespace woven
