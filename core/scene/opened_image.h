#pragma once
// The one door through which woven decodes an image with OpenImageIO: the file read within
// kMaxImageFileBytes, the format recognised by its first bytes, an EXR's headers and the image's
// size checked against the limits (image_io.h) before any pixel is. The scene's textures and
// environments (image_io.cpp) and the render layer's frame files (frame_io.cpp) both open
// images here, so untrusted input meets the same checks.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

#include "image_io.h"

namespace woven {

// The formats woven reads, by their first bytes: glTF textures are PNG, JPEG or WebP
// (EXT_texture_webp), environment maps Radiance HDR or OpenEXR. Anything else is refused by
// name before a decoder sees it.
enum class ImageFormat { Png, Jpeg, Webp, Hdr, Exr };

// OpenImageIO 2.4's IOMemReader::pread copies from before its buffer for a small read at a
// negative offset (its bounds check wraps around): an EXR whose line offsets lead there was
// read out of bounds (found by fuzz/fuzz_exr). Reads outside the bytes read nothing.
class CheckedMemReader : public OIIO::Filesystem::IOMemReader {
public:
    using IOMemReader::IOMemReader;
    size_t pread(void* buf, size_t size, int64_t offset) override {
        if (offset < 0 || uint64_t(offset) > this->size()) return 0;
        return IOMemReader::pread(buf, size, offset);
    }
};

// An image opened from memory, its size checked against the limits before any pixel is read.
struct OpenedImage {
    std::unique_ptr<CheckedMemReader> memory;
    std::unique_ptr<OIIO::ImageInput> input;
    ImageFormat format;
    const OIIO::ImageSpec& spec() const { return input->spec(); }
};

// Throws ImageError naming `name` for any format woven does not read and any limit exceeded.
OpenedImage openImage(const unsigned char* data, size_t size, const std::string& name);
// OpenImageIO's last error for `input` (null: its global one), in one line.
std::string oiioError(const OIIO::ImageInput* input);
// A file's bytes, refusing one over kMaxImageFileBytes or not a regular file (ImageError).
std::vector<unsigned char> readImageFile(const std::string& path);

}  // namespace woven
