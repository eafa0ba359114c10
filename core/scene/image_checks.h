#pragma once
// What every decoder of woven's meets first, so that untrusted input meets the same checks
// whichever library decodes it: the file read within kMaxImageFileBytes, the format recognised by
// its first bytes, and the image's size checked against the limits (image_io.h) before any pixel
// is decoded. The scene's textures and environments (image_io.cpp) and the render layer's frame
// files (exr_file.cpp, frame_io.cpp) both start here.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace woven {

// The formats woven reads: glTF textures are PNG, JPEG or WebP (EXT_texture_webp), environment
// maps Radiance HDR or OpenEXR.
enum class ImageFormat { Png, Jpeg, Webp, Hdr, Exr };

// The format by its first bytes; anything else is refused by name (ImageError naming `name`)
// before a decoder sees it.
ImageFormat detectImageFormat(const unsigned char* data, size_t size, const std::string& name);

// Throws ImageError naming `name` for an empty image or one over the limits (kMaxImageSide,
// kMaxImagePixels, kMaxImageChannels, kMaxImageDecodedBytes with every channel as 32 bits).
void checkImageSize(int64_t width, int64_t height, int channels, const std::string& name);

// A file's bytes, refusing one over kMaxImageFileBytes or not a regular file (ImageError).
std::vector<unsigned char> readImageFile(const std::string& path);

}  // namespace woven
