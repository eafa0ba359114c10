#pragma once
// Reading and writing woven::Image: PNG/JPEG/HDR/EXR in, PNG (display-ready) and EXR (linear,
// with a per-pixel sample count so renders of disjoint sample ranges can be merged) out.
// Every failure throws ImageError naming the file; every write is atomic (atomic_file.h).
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact_sum.h"
#include "frame_identity.h"
#include "sample_range.h"
#include "scene_description.h"
#include "srgb.h"  // PNG and JPEG are sRGB-encoded

namespace woven {

struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What woven reads of an image, checked before any pixel is decoded: images from other people
// can claim any size. 16384 x 16384 RGBA floats would be 4 GiB; textures and environment maps
// of 16k on a side with 128 Mpixels and 1 GiB of file cover every real asset.
constexpr int kMaxImageSide = 32768;
constexpr int64_t kMaxImagePixels = int64_t(1) << 27;
constexpr int kMaxImageChannels = 64;
// All channels decoded as 32-bit values: a 128 Mpixel RGBA texture (2 GiB), or an 8k x 8k EXR part
// with its 16 channels of colour, count and sums (4 GiB).
constexpr int64_t kMaxImageDecodedBytes = int64_t(4) << 30;
constexpr size_t kMaxImageFileBytes = size_t(1) << 30;

// How 8- and 16-bit channels are turned into linear floats. Colour textures (baseColor,
// emissive) are sRGB-encoded; data textures (roughness, normals) are already linear.
// Float formats (.hdr, .exr) are always linear and ignore this.
enum class ChannelEncoding { Srgb, Linear };

// Reads PNG, JPEG, Radiance HDR or OpenEXR (its R, G, B channels; a file with only Y is read
// as grey), recognised by their first bytes; any other format is refused by name. Decoding is
// OpenImageIO's (libpng, libjpeg-turbo, OpenEXR). Grey images are expanded to RGB; alpha is
// dropped.
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

// A linear image with, optionally, how many samples each pixel's value is the mean of, and what
// a render keeps so that renders of disjoint sample ranges merge exactly: the exact sums of the
// samples, which samples they are and which frame they are samples of.
struct ExrImage {
    Image image;
    std::vector<float> sampleCount;        // empty, or one per pixel (channel "N")
    std::vector<ExactSum> sampleSums{};    // empty, or three per pixel: R, G, B
    std::optional<SampleRange> samples{};  // the same for every pixel
    std::optional<FrameIdentity> frame{};  // none in files of other tools and of woven before it
};
enum class ExrPrecision { Half, Float };

// Writes channels B, G, R (in `precision`) and, when sampleCount is not empty, N (always 32-bit
// float, exact for counts below 2^24), ZIP-compressed. Sample sums go to 32-bit unsigned
// channels sum.B0-sum.B3, sum.G0-sum.G3, sum.R0-sum.R3 (ExactSum::words(), least significant
// first), the sample range to attributes wovenFirstSample and wovenSampleCount (decimal strings:
// EXR has no 64-bit integer attribute; files of earlier versions have ints, which are read too),
// the frame's identity to wovenScene, wovenSeed (strings), wovenIntegrator (a string),
// wovenMaxDepth and wovenFilter (ints); other tools read R, G, B (and N) and ignore the rest.
void writeExr(const std::string& path, const ExrImage& exr,
              ExrPrecision precision = ExrPrecision::Half);
ExrImage readExr(const std::string& path);

// ".exr" for "out/Frame.EXR": the extension with its dot, in lower case; "" for none.
std::string lowerExtension(const std::string& path);

// A rendered frame, by its file's extension (either case): .exr keeps the linear radiance in
// 32-bit floats and the sample counts; .png is display-transformed. Others throw ImageError.
void writeFrame(const std::string& path, const ExrImage& frame, const DisplayTransform& png);
// Throws the ImageError writeFrame would for `path`'s extension, or the FileWriteError for a
// folder that is missing or not writable (atomic_file.h): check before a long render.
void checkFrameFileName(const std::string& path);
// "out.exr" -> "out.partial.exr": where an unfinished frame goes, so it never takes the name of
// a finished one.
std::string partialFrameName(const std::string& path);

}  // namespace woven
