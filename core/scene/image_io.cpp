#include "image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <webp/decode.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>

#include "atomic_file.h"
#include "exr_file.h"
#include "image_checks.h"
#include "jpeg_decoding.h"
#include "png_decoding.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
}

// An image as decoded, before woven's colour handling: `channels` interleaved values a pixel,
// from the top row.
struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> bytes;  // 8-bit sources
    // 16-bit sources scaled to 0..1; float sources as they are. 8- and 16-bit values are scaled
    // by multiplying with the reciprocal, as OpenImageIO did, so textures decode as before.
    std::vector<float> floats;
    bool floatFormat = false;          // Radiance HDR and OpenEXR: linear, never colour-decoded

    float value(size_t pixel, int c) const {
        const size_t i = pixel * size_t(channels) + size_t(c);
        return bytes.empty() ? floats[i] : bytes[i] * (1.0f / 255.0f);
    }
};

// RGBA from 1 to 4 channels (grey, grey + alpha, RGB, RGBA).
template <typename T, typename Get>
T channelOf(int channels, int c, T opaque, Get get) {
    if (channels <= 2) return c < 3 ? get(0) : (channels == 2 ? get(1) : opaque);
    if (c < 3) return get(c);
    return channels >= 4 ? get(3) : opaque;
}

// stb_image's reason for a failure is a word or two ("outofdata"): said as its.
std::string stbReason() {
    return std::string("stb_image says \"") + stbi_failure_reason() + "\"";
}

// Radiance HDR through stb_image, checked against the limits before it decodes.
Pixels decodeHdr(const unsigned char* data, size_t size, const std::string& name) {
    const std::string cannot = "cannot decode the Radiance HDR image: ";
    if (size > size_t(std::numeric_limits<int>::max())) fail(name, cannot + "the file is over 2 GiB");
    // stb_image recognises Radiance HDR by a whole first line; other bytes would go on to its
    // loosely recognised formats (TGA).
    const auto firstLineIs = [&](const std::string& line) {
        return size >= line.size() && std::memcmp(data, line.data(), line.size()) == 0;
    };
    if (!firstLineIs("#?RADIANCE\n") && !firstLineIs("#?RGBE\n")) fail(name, cannot + "its first line is neither #?RADIANCE nor #?RGBE");
    const int length = int(size);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels)) fail(name, cannot + stbReason());
    checkImageSize(width, height, channels, name);
    Pixels p;
    p.floatFormat = true;
    float* decoded = stbi_loadf_from_memory(data, length, &p.width, &p.height, &p.channels, 0);
    if (!decoded) fail(name, cannot + stbReason());
    const std::unique_ptr<float, void (*)(void*)> owned(decoded, stbi_image_free);
    if (p.width != width || p.height != height || p.channels < 1 || p.channels > 4)
        fail(name, cannot + "its size changed as it was decoded");
    p.floats.assign(decoded, decoded + size_t(width) * size_t(height) * size_t(p.channels));
    return p;
}

// An OpenEXR image's R, G, B (and A), or its Y (and A) as grey, by name.
Pixels decodeExr(const unsigned char* data, size_t size, const std::string& name) {
    const ExrFile file = readExrFile(data, size, name);
    std::vector<const ExrChannel*> used;
    for (const char* c : {"R", "G", "B"})
        if (const ExrChannel* channel = file.channel(c)) used.push_back(channel);
    if (used.size() != 3) used = {file.channel("Y")};
    if (!used[0]) fail(name, "no R, G, B (or Y) channels");
    if (const ExrChannel* alpha = file.channel("A")) used.push_back(alpha);
    Pixels p;
    p.width = file.width;
    p.height = file.height;
    p.channels = int(used.size());
    p.floatFormat = true;
    const size_t count = size_t(file.width) * size_t(file.height);
    p.floats.resize(count * used.size());
    for (size_t c = 0; c < used.size(); ++c) {
        if (used[c]->type == ExrChannelType::Uint) fail(name, "the channel " + used[c]->name + " is not half or float");
        for (size_t i = 0; i < count; ++i) p.floats[i * used.size() + c] = used[c]->values[i];
    }
    return p;
}

// Alpha as stored (glTF's is not premultiplied), as libwebp decodes it.
Pixels decodeWebp(const unsigned char* data, size_t size, const std::string& name) {
    Pixels p;
    if (!WebPGetInfo(data, size, &p.width, &p.height)) fail(name, "cannot decode the WebP image: its header is corrupt");
    checkImageSize(p.width, p.height, 4, name);
    p.channels = 4;
    p.bytes.resize(size_t(p.width) * size_t(p.height) * 4);
    if (!WebPDecodeRGBAInto(data, size, p.bytes.data(), p.bytes.size(), p.width * 4))
        fail(name, "cannot decode the WebP image: its data is corrupt");
    return p;
}

Pixels decodePixels(const unsigned char* data, size_t size, const std::string& name) {
    const ImageFormat format = detectImageFormat(data, size, name);
    if (format == ImageFormat::Exr) return decodeExr(data, size, name);
    if (format == ImageFormat::Hdr) return decodeHdr(data, size, name);
    if (format == ImageFormat::Png) {
        PngPixels png = decodePng(data, size, name);
        Pixels p;
        p.width = png.width;
        p.height = png.height;
        p.channels = png.channels;
        p.bytes = std::move(png.bytes);
        p.floats.resize(png.words.size());
        for (size_t i = 0; i < png.words.size(); ++i) p.floats[i] = png.words[i] * (1.0f / 65535.0f);
        return p;
    }
    if (format == ImageFormat::Jpeg) {
        JpegPixels jpeg = decodeJpeg(data, size, name);
        Pixels p;
        p.width = jpeg.width;
        p.height = jpeg.height;
        p.channels = jpeg.channels;
        p.bytes = std::move(jpeg.bytes);
        return p;
    }
    return decodeWebp(data, size, name);
}

}  // namespace

Image decodeImage(const unsigned char* data, size_t size, ChannelEncoding encoding, const std::string& name) {
    const Pixels pixels = decodePixels(data, size, name);
    Image image;
    image.width = pixels.width;
    image.height = pixels.height;
    image.pixels.resize(size_t(pixels.width) * size_t(pixels.height));
    const bool srgb = !pixels.floatFormat && encoding == ChannelEncoding::Srgb;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = channelOf(pixels.channels, c, 1.0f, [&](int k) { return pixels.value(i, k); });
            image.pixels[i][c] = srgb ? srgbToLinear(v) : v;
        }
    return image;
}

TextureImage decodeTexture(const unsigned char* data, size_t size, const std::string& name) {
    const Pixels pixels = decodePixels(data, size, name);
    TextureImage texture;
    texture.name = name;
    texture.width = pixels.width;
    texture.height = pixels.height;
    const size_t count = size_t(pixels.width) * size_t(pixels.height);
    const int n = pixels.channels;
    if (!pixels.bytes.empty()) {
        texture.bytes.resize(count);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 4; ++c)
                texture.bytes[i][c] = channelOf(n, c, (unsigned char)255, [&](int k) { return pixels.bytes[i * size_t(n) + size_t(k)]; });
        return texture;
    }
    // 16-bit and float sources: normalised floats, still undecoded (TextureRef::srgb decides).
    texture.floats.resize(count);
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < 4; ++c) texture.floats[i][c] = channelOf(n, c, 1.0f, [&](int k) { return pixels.floats[i * size_t(n) + size_t(k)]; });
    return texture;
}

Image readImage(const std::string& path, ChannelEncoding encoding) {
    const std::vector<unsigned char> bytes = readImageFile(path);
    return decodeImage(bytes.data(), bytes.size(), encoding, path);
}

std::vector<unsigned char> encodeTexturePng(const TextureImage& texture) {
    if (texture.width <= 0 || texture.height <= 0 || texture.bytes.size() != size_t(texture.width) * texture.height)
        fail(texture.name, "cannot encode an empty or float texture as an 8-bit PNG");
    std::vector<unsigned char> png;
    const auto append = [](void* out, void* data, int size) {
        auto* bytes = static_cast<unsigned char*>(data);
        static_cast<std::vector<unsigned char>*>(out)->insert(static_cast<std::vector<unsigned char>*>(out)->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &png, texture.width, texture.height, 4, &texture.bytes[0].x, texture.width * 4))
        fail(texture.name, "cannot encode the PNG data");
    return png;
}

void writeTexturePng(const std::string& path, const TextureImage& texture) {
    const std::vector<unsigned char> png = encodeTexturePng(texture);
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
        if (!out.flush()) throw ImageError("cannot write the file");
    });
}

}  // namespace woven
