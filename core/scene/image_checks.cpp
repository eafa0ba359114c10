#include "image_checks.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>

#include "file_reading.h"
#include "image_io.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw ImageError(name + ": " + problem);
}

}  // namespace

ImageFormat detectImageFormat(const unsigned char* data, size_t size, const std::string& name) {
    const auto startsWith = [&](std::initializer_list<unsigned char> magic) {
        return size >= magic.size() && std::equal(magic.begin(), magic.end(), data);
    };
    const auto startsWithText = [&](const char* text) {
        const size_t n = std::strlen(text);
        return size >= n && std::memcmp(data, text, n) == 0;
    };
    if (startsWith({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return ImageFormat::Png;
    if (startsWith({0xff, 0xd8, 0xff})) return ImageFormat::Jpeg;
    if (size >= 12 && std::memcmp(data, "RIFF", 4) == 0 && std::memcmp(data + 8, "WEBP", 4) == 0) return ImageFormat::Webp;
    if (startsWithText("#?RADIANCE") || startsWithText("#?RGBE")) return ImageFormat::Hdr;
    if (startsWith({0x76, 0x2f, 0x31, 0x01})) return ImageFormat::Exr;
    std::string what = "an unknown format";
    if (startsWithText("GIF8")) what = "GIF";
    else if (startsWithText("BM")) what = "BMP";
    else if (startsWith({'I', 'I', 42, 0}) || startsWith({'M', 'M', 0, 42})) what = "TIFF";
    else if (startsWith({0xab, 'K', 'T', 'X'})) what = "KTX";
    else if (startsWithText("DDS ")) what = "DDS";
    else if (size >= 2 && data[0] == 'P' && data[1] >= '1' && data[1] <= '7') what = "PNM";
    else if (size >= 18 && (data[2] == 1 || data[2] == 2 || data[2] == 3 || data[2] >= 9)) what = "TGA or an unknown format";
    fail(name, "the image is " + what + ": woven reads PNG, JPEG, WebP, Radiance HDR (.hdr) and OpenEXR (.exr)");
}

void checkImageSize(int64_t width, int64_t height, int channels, const std::string& name) {
    if (width <= 0 || height <= 0)
        fail(name, "the image is empty (" + std::to_string(width) + " x " + std::to_string(height) + ")");
    if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
        fail(name, "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                       ", more than woven reads (" + std::to_string(kMaxImageSide) + " on a side, " +
                       std::to_string(kMaxImagePixels / (1 << 20)) + " Mpixels)");
    if (channels <= 0 || channels > kMaxImageChannels)
        fail(name, "the image has " + std::to_string(channels) + " channels (woven reads 1 to " +
                       std::to_string(kMaxImageChannels) + ")");
    const int64_t decodedBytes = width * height * channels * 4;
    if (decodedBytes > kMaxImageDecodedBytes)
        fail(name, "the image's " + std::to_string(width) + " x " + std::to_string(height) + " pixels of " +
                       std::to_string(channels) + " channels decode to " + std::to_string(decodedBytes >> 20) +
                       " MiB, more than woven's limit of " + std::to_string(kMaxImageDecodedBytes >> 20) + " MiB");
}

std::vector<unsigned char> readImageFile(const std::string& path) {
    try {
        return readRegularFile(path, kMaxImageFileBytes);
    } catch (const FileReadError& e) {
        throw ImageError(e.what());
    }
}

}  // namespace woven
