#include "image_io.h"

#include <stb_image_write.h>
#include <webp/decode.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "atomic_file.h"
#include "exr_header.h"
#include "file_reading.h"
#include "opened_image.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
}

ImageFormat detectFormat(const unsigned char* data, size_t size, const std::string& name) {
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

const char* formatExtension(ImageFormat f) {
    switch (f) {
        case ImageFormat::Png: return ".png";
        case ImageFormat::Jpeg: return ".jpg";
        case ImageFormat::Webp: return ".webp";
        case ImageFormat::Hdr: return ".hdr";
        case ImageFormat::Exr: return ".exr";
    }
    return "";
}

// The limits, before any pixel is decoded.
void checkImageSize(int64_t width, int64_t height, int channels, const std::string& name) {
    if (width <= 0 || height <= 0)
        fail(name, "the image is empty (" + std::to_string(width) + " x " + std::to_string(height) + ")");
    if (width > kMaxImageSide || height > kMaxImageSide ||
        width * height > kMaxImagePixels)
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

}  // namespace

std::string oiioError(const OIIO::ImageInput* input) {
    std::string message = input ? input->geterror() : OIIO::geterror();
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    return message.empty() ? "unknown error" : message;
}

OpenedImage openImage(const unsigned char* data, size_t size, const std::string& name) {
    OpenedImage image;
    image.format = detectFormat(data, size, name);
    // OpenEXR allocates a part's line buffers as it opens the file: the limits come first.
    if (image.format == ImageFormat::Exr)
        for (const ExrPartSize& part : checkExrHeaders(data, size, name))
            if (part.channels > 0) checkImageSize(part.width, part.height, part.channels, name);
    image.memory = std::make_unique<CheckedMemReader>(data, size);
    // The name only tells OpenImageIO which decoder to use: the bytes come from memory. Alpha
    // stays as stored (glTF's is not premultiplied; OpenImageIO would premultiply it).
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    void* proxy = image.memory.get();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    // Bytes that the decoder refuses would otherwise go to every other reader OpenImageIO has
    // (DICOM, JPEG 2000, ...): slow, and far more decoders than woven means to expose.
    static const bool onlyTheNamedDecoder = OIIO::attribute("try_all_readers", 0);
    (void)onlyTheNamedDecoder;
    image.input = OIIO::ImageInput::open(std::string("image") + formatExtension(image.format), &config, image.memory.get());
    if (!image.input) fail(name, "cannot decode the image: " + oiioError(nullptr));
    const OIIO::ImageSpec& spec = image.input->spec();
    if (spec.deep) fail(name, "deep OpenEXR images are not supported");
    if (spec.depth != 1) fail(name, "the image is empty (" + std::to_string(spec.width) + " x " + std::to_string(spec.height) + ")");
    checkImageSize(spec.width, spec.height, spec.nchannels, name);
    return image;
}

namespace {

// OpenImageIO 2.4 premultiplies WebP's alpha whatever it is asked: libwebp decodes it as stored.
TextureImage decodeWebpTexture(const unsigned char* data, size_t size, const std::string& name) {
    int width = 0, height = 0;
    if (!WebPGetInfo(data, size, &width, &height)) fail(name, "cannot decode the WebP image: its header is corrupt");
    checkImageSize(width, height, 4, name);
    TextureImage texture;
    texture.name = name;
    texture.width = width;
    texture.height = height;
    texture.bytes.resize(size_t(width) * size_t(height));
    if (!WebPDecodeRGBAInto(data, size, &texture.bytes[0].x, texture.bytes.size() * 4, width * 4))
        fail(name, "cannot decode the WebP image: its data is corrupt");
    return texture;
}

// All channels of the first subimage as `type`, interleaved.
template <typename T>
std::vector<T> readPixels(OpenedImage& image, OIIO::TypeDesc type, const std::string& name) {
    const OIIO::ImageSpec& spec = image.spec();
    std::vector<T> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    if (!image.input->read_image(0, 0, 0, spec.nchannels, type, pixels.data()))
        fail(name, "cannot decode the image: " + oiioError(image.input.get()));
    return pixels;
}

// RGBA from 1 to 4 channels (grey, grey + alpha, RGB, RGBA; more: the first four).
template <typename T>
T channelOf(const T* pixel, int channels, int c, T opaque) {
    if (channels <= 2) return c < 3 ? pixel[0] : (channels == 2 ? pixel[1] : opaque);
    if (c < 3) return pixel[c];
    return channels >= 4 ? pixel[3] : opaque;
}

}  // namespace

Image decodeImage(const unsigned char* data, size_t size, ChannelEncoding encoding, const std::string& name) {
    OpenedImage opened = openImage(data, size, name);
    const OIIO::ImageSpec& spec = opened.spec();
    const bool floats = opened.format == ImageFormat::Hdr || opened.format == ImageFormat::Exr;
    const std::vector<float> pixels = readPixels<float>(opened, OIIO::TypeFloat, name);
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.pixels.resize(size_t(spec.width) * size_t(spec.height));
    const bool srgb = !floats && encoding == ChannelEncoding::Srgb;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const float* pixel = &pixels[i * size_t(spec.nchannels)];
        for (int c = 0; c < 3; ++c) {
            const float v = channelOf(pixel, spec.nchannels, c, 1.0f);
            image.pixels[i][c] = srgb ? srgbToLinear(v) : v;
        }
    }
    return image;
}

TextureImage decodeTexture(const unsigned char* data, size_t size, const std::string& name) {
    if (detectFormat(data, size, name) == ImageFormat::Webp) return decodeWebpTexture(data, size, name);
    OpenedImage opened = openImage(data, size, name);
    const OIIO::ImageSpec& spec = opened.spec();
    TextureImage texture;
    texture.name = name;
    texture.width = spec.width;
    texture.height = spec.height;
    const size_t count = size_t(spec.width) * size_t(spec.height);
    if (spec.format == OIIO::TypeDesc::UINT8) {
        const std::vector<unsigned char> pixels = readPixels<unsigned char>(opened, OIIO::TypeDesc::UINT8, name);
        texture.bytes.resize(count);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 4; ++c)
                texture.bytes[i][c] = channelOf(&pixels[i * size_t(spec.nchannels)], spec.nchannels, c, (unsigned char)255);
        return texture;
    }
    // 16-bit and float sources: normalised floats, still undecoded (TextureRef::srgb decides).
    const std::vector<float> pixels = readPixels<float>(opened, OIIO::TypeFloat, name);
    texture.floats.resize(count);
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < 4; ++c) texture.floats[i][c] = channelOf(&pixels[i * size_t(spec.nchannels)], spec.nchannels, c, 1.0f);
    return texture;
}

std::vector<unsigned char> readImageFile(const std::string& path) {
    try {
        return readRegularFile(path, kMaxImageFileBytes);
    } catch (const FileReadError& e) {
        throw ImageError(e.what());
    }
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
