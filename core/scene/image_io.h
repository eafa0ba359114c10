#pragma once
// Decoding images into woven::Image and TextureImage: PNG/JPEG/WebP/HDR/EXR textures and
// environment maps, read as untrusted input within the limits below, and textures encoded back
// to PNG as they are. A frame's files (EXR with its sample counts, display-ready PNG) are the
// render layer's (frame_io.h). Every failure throws ImageError naming the file; every write is
// atomic (atomic_file.h).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_description.h"
#include "srgb.h"  // PNG and JPEG are sRGB-encoded

namespace woven {

struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What woven reads of an image, checked before any pixel is decoded: images from other people
// can claim any size. 16384 x 16384 RGBA floats would be 4 GiB; textures and environment maps
// of 16k on a side with 128 Mpixels cover every real asset, and 2 GiB of file a 3840 x 2160
// frame file of woven's (about 1.4 GB with its passes and exact sums).
constexpr int kMaxImageSide = 32768;
constexpr int64_t kMaxImagePixels = int64_t(1) << 27;
// A frame file of woven's has 122 channels (frame_io.h): beauty, noisy beauty, passes, count and
// the exact sums' words.
constexpr int kMaxImageChannels = 128;
// All channels decoded as 32-bit values: a 128 Mpixel RGBA texture (2 GiB), or a 3840 x 2160
// frame file with its 122 channels (3.8 GiB). The fuzz build sets a lower one (CMakeLists.txt).
#ifndef WOVEN_MAX_IMAGE_DECODED_MIB
#define WOVEN_MAX_IMAGE_DECODED_MIB 4096
#endif
constexpr int64_t kMaxImageDecodedBytes = int64_t(WOVEN_MAX_IMAGE_DECODED_MIB) << 20;
constexpr size_t kMaxImageFileBytes = size_t(2) << 30;

// How 8- and 16-bit channels are turned into linear floats. Colour textures (baseColor,
// emissive) are sRGB-encoded; data textures (roughness, normals) are already linear.
// Float formats (.hdr, .exr) are always linear and ignore this.
enum class ChannelEncoding { Srgb, Linear };

// Reads PNG, JPEG, WebP, Radiance HDR or OpenEXR (its R, G, B channels; a file with only Y is
// read as grey), recognised by their first bytes; any other format is refused by name. Decoding
// is each format's own library's: libpng, libjpeg-turbo, libwebp, OpenEXR, and stb_image for
// Radiance HDR. Grey images are expanded to RGB; alpha is dropped.
Image readImage(const std::string& path, ChannelEncoding encoding = ChannelEncoding::Srgb);

// The same for an encoded image held in memory (a texture embedded in a .glb);
// `name` identifies it in error messages.
Image decodeImage(const unsigned char* data, size_t size, ChannelEncoding encoding,
                  const std::string& name);

// A texture (PNG, JPEG, or a float format) as stored, without colour decoding: RGBA, 8-bit
// sources kept as bytes (see TextureImage). `name` identifies it in error messages.
TextureImage decodeTexture(const unsigned char* data, size_t size, const std::string& name);

// An 8-bit texture (TextureImage::bytes, RGBA) encoded as a PNG as it is: no colour transform,
// since a glTF texture's bytes are already what its use decodes (sRGB colour or linear data).
// Throws ImageError for a float or empty texture.
std::vector<unsigned char> encodeTexturePng(const TextureImage& texture);
void writeTexturePng(const std::string& path, const TextureImage& texture);  // atomic

}  // namespace woven
