#include "image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/half.h>
#include <OpenImageIO/imageio.h>
#include <stb_image_write.h>
#include <webp/decode.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "atomic_file.h"
#include "exr_header.h"
#include "file_reading.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
}

// The formats woven reads, by their first bytes: glTF textures are PNG, JPEG or WebP
// (EXT_texture_webp), environment maps Radiance HDR or OpenEXR. Anything else is refused by
// name before a decoder sees it.
enum class ImageFormat { Png, Jpeg, Webp, Hdr, Exr };

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

std::string oiioError(const OIIO::ImageInput* input) {
    std::string message = input ? input->geterror() : OIIO::geterror();
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    return message.empty() ? "unknown error" : message;
}

// The limits, before any pixel is decoded.
void checkImageSize(int width, int height, int channels, const std::string& name) {
    if (width <= 0 || height <= 0)
        fail(name, "the image is empty (" + std::to_string(width) + " x " + std::to_string(height) + ")");
    if (width > kMaxImageSide || height > kMaxImageSide ||
        int64_t(width) * height > kMaxImagePixels)
        fail(name, "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                       ", more than woven reads (" + std::to_string(kMaxImageSide) + " on a side, " +
                       std::to_string(kMaxImagePixels / (1 << 20)) + " Mpixels)");
    if (channels <= 0 || channels > kMaxImageChannels)
        fail(name, "the image has " + std::to_string(channels) + " channels (woven reads 1 to " +
                       std::to_string(kMaxImageChannels) + ")");
    const int64_t decodedBytes = int64_t(width) * height * channels * 4;
    if (decodedBytes > kMaxImageDecodedBytes)
        fail(name, "the image's " + std::to_string(width) + " x " + std::to_string(height) + " pixels of " +
                       std::to_string(channels) + " channels decode to " + std::to_string(decodedBytes >> 20) +
                       " MiB, more than woven's limit of " + std::to_string(kMaxImageDecodedBytes >> 20) + " MiB");
}

OpenedImage openImage(const unsigned char* data, size_t size, const std::string& name) {
    OpenedImage image;
    image.format = detectFormat(data, size, name);
    if (image.format == ImageFormat::Exr) checkExrAttributeSizes(data, size, name);
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

// The sum channels' names, in the order ExactSum::words() gives them, R, G, B.
std::string sumChannelName(int rgb, int word) {
    return std::string("sum.") + "RGB"[rgb] + std::to_string(word);
}

const char* const kFirstSampleAttribute = "wovenFirstSample";
const char* const kSampleCountAttribute = "wovenSampleCount";

// A whole number written as decimal digits, all of `text`.
template <typename T>
bool parseWhole(const std::string& text, T* value) {
    const char* end = text.data() + text.size();
    const auto [last, error] = std::from_chars(text.data(), end, *value);
    return !text.empty() && error == std::errc() && last == end;
}

// A sample index: a decimal string, or an int as versions before 64-bit ranges wrote it.
bool readSampleIndex(const OIIO::ParamValue& value, int64_t* index) {
    if (value.type() == OIIO::TypeInt) {
        *index = value.get_int();
        return true;
    }
    return value.type() == OIIO::TypeString && parseWhole(value.get_string(), index);
}

std::string readSampleRange(const OIIO::ImageSpec& spec, std::optional<SampleRange>* samples) {
    const OIIO::ParamValue* first = spec.find_attribute(kFirstSampleAttribute);
    const OIIO::ParamValue* count = spec.find_attribute(kSampleCountAttribute);
    if (!first && !count) return "";
    if (!first || !count)
        return std::string("has only one of the attributes ") + kFirstSampleAttribute + " and " + kSampleCountAttribute;
    int64_t f = 0, c = 0;
    if (!readSampleIndex(*first, &f) || !readSampleIndex(*count, &c))
        return std::string("the attributes ") + kFirstSampleAttribute + " and " + kSampleCountAttribute +
               " must be whole numbers (decimal strings, or ints)";
    if (!withinSampleIndexLimit(f, c))
        return "has the sample range first " + std::to_string(f) + ", count " + std::to_string(c) +
               ", which is not within samples 0 to 2^62 (" + std::to_string(kSampleIndexLimit) + ")";
    *samples = SampleRange{f, c};
    return "";
}

const char* const kSceneAttribute = "wovenScene";
const char* const kSeedAttribute = "wovenSeed";
const char* const kIntegratorAttribute = "wovenIntegrator";
const char* const kMaxDepthAttribute = "wovenMaxDepth";
const char* const kFilterAttribute = "wovenFilter";

std::string readFrameIdentity(const OIIO::ImageSpec& spec, std::optional<FrameIdentity>* frame) {
    const char* const names[] = {kSceneAttribute, kSeedAttribute, kIntegratorAttribute, kMaxDepthAttribute, kFilterAttribute};
    int found = 0;
    for (const char* name : names) found += spec.find_attribute(name) != nullptr;
    if (found == 0) return "";
    const std::string all = "wovenScene, wovenSeed, wovenIntegrator, wovenMaxDepth and wovenFilter";
    if (found != 5) return "has only some of the attributes " + all;
    const OIIO::ParamValue& scene = *spec.find_attribute(kSceneAttribute);
    const OIIO::ParamValue& seed = *spec.find_attribute(kSeedAttribute);
    const OIIO::ParamValue& integrator = *spec.find_attribute(kIntegratorAttribute);
    const OIIO::ParamValue& maxDepth = *spec.find_attribute(kMaxDepthAttribute);
    const OIIO::ParamValue& filter = *spec.find_attribute(kFilterAttribute);
    FrameIdentity f;
    if (scene.type() != OIIO::TypeString || seed.type() != OIIO::TypeString || integrator.type() != OIIO::TypeString ||
        maxDepth.type() != OIIO::TypeInt || filter.type() != OIIO::TypeInt || !parseWhole(seed.get_string(), &f.seed))
        return "the attributes " + all + " must be a string, a decimal string, a string and two ints";
    f.scene = scene.get_string();
    f.integrator = integrator.get_string();
    f.maxDepth = maxDepth.get_int();
    f.filterWeave = filter.get_int() != 0;
    // Merge names them in its messages: only what woven writes.
    const bool hex = f.scene.size() == 16 && f.scene.find_first_not_of("0123456789abcdef") == std::string::npos;
    const char* const integrators[] = {"path", "bdpt", "auto: path", "auto: bdpt", "auto"};
    if (!hex || std::find(std::begin(integrators), std::end(integrators), f.integrator) == std::end(integrators) ||
        f.maxDepth < 1 || (filter.get_int() != 0 && filter.get_int() != 1))
        return "has attributes " + all + " that woven does not write";
    *frame = f;
    return "";
}

float toneMap(float c, ToneMap curve) {
    switch (curve) {
        case ToneMap::Clamp: return c;
        case ToneMap::Reinhard: return c / (1.0f + c);
        case ToneMap::Aces:
            return (c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f);
    }
    return c;
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

ExrImage readExr(const std::string& path) {
    const std::vector<unsigned char> bytes = readImageFile(path);
    OpenedImage opened = openImage(bytes.data(), bytes.size(), path);
    if (opened.format != ImageFormat::Exr) fail(path, "not an OpenEXR file");
    const OIIO::ImageSpec& spec = opened.spec();
    // Every channel in its own type: the sums are 32-bit unsigned words, which floats would round.
    std::vector<unsigned char> raw(spec.image_bytes(true));
    if (!opened.input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeUnknown, raw.data()))
        fail(path, "cannot decode the OpenEXR image: " + oiioError(opened.input.get()));
    std::vector<size_t> offset(size_t(spec.nchannels), 0);
    for (int c = 1; c < spec.nchannels; ++c) offset[size_t(c)] = offset[size_t(c) - 1] + spec.channelformat(c - 1).size();
    const size_t pixelBytes = spec.pixel_bytes(true);
    const auto find = [&](const std::string& name) {
        for (int c = 0; c < spec.nchannels; ++c)
            if (spec.channelnames[size_t(c)] == name) return c;
        return -1;
    };
    const auto asFloat = [&](int c, size_t i) {
        const unsigned char* p = &raw[i * pixelBytes + offset[size_t(c)]];
        float v = 0.0f;
        OIIO::convert_type(spec.channelformat(c), p, OIIO::TypeFloat, &v, 1);
        return v;
    };
    int r = find("R"), g = find("G"), b = find("B");
    if (r < 0 || g < 0 || b < 0) r = g = b = find("Y");
    if (r < 0) fail(path, "no R, G, B (or Y) channels");
    ExrImage result;
    Image& image = result.image;
    image.width = spec.width;
    image.height = spec.height;
    const size_t count = size_t(spec.width) * size_t(spec.height);
    image.pixels.resize(count);
    for (size_t i = 0; i < count; ++i) image.pixels[i] = {asFloat(r, i), asFloat(g, i), asFloat(b, i)};
    if (const int n = find("N"); n >= 0) {
        result.sampleCount.resize(count);
        for (size_t i = 0; i < count; ++i) result.sampleCount[i] = asFloat(n, i);
    }
    int words[3][4], found = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 4; ++w) {
            words[c][w] = find(sumChannelName(c, w));
            if (words[c][w] >= 0 && spec.channelformat(words[c][w]) != OIIO::TypeDesc::UINT32)
                fail(path, "the sample-sum channel " + sumChannelName(c, w) + " is not 32-bit unsigned");
            found += words[c][w] >= 0;
        }
    if (found != 0 && found != 12) fail(path, "some of the 32-bit unsigned sample-sum channels sum.R0-sum.B3 are missing");
    if (found == 12) {
        result.sampleSums.resize(3 * count);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) {
                std::array<uint32_t, 4> w{};
                for (int k = 0; k < 4; ++k)
                    std::memcpy(&w[size_t(k)], &raw[i * pixelBytes + offset[size_t(words[c][k])]], 4);
                result.sampleSums[3 * i + size_t(c)] = ExactSum::fromWords(w);
            }
    }
    if (const std::string problem = readSampleRange(spec, &result.samples); !problem.empty()) fail(path, problem);
    if (const std::string problem = readFrameIdentity(spec, &result.frame); !problem.empty()) fail(path, problem);
    return result;
}

Image readImage(const std::string& path, ChannelEncoding encoding) {
    const std::vector<unsigned char> bytes = readImageFile(path);
    return decodeImage(bytes.data(), bytes.size(), encoding, path);
}

glm::u8vec3 displayColor(const glm::vec3& linear, const DisplayTransform& transform) {
    const float scale = std::exp2(transform.exposure);
    glm::u8vec3 out;
    for (int c = 0; c < 3; ++c) {
        // Negative values are black before the curve: ACES's rational fit turns large negative
        // values positive. NaN (a bug upstream) shows as black rather than undefined behaviour.
        float v = toneMap(std::max(linear[c] * scale, 0.0f), transform.toneMap);
        v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
        out[c] = static_cast<unsigned char>(std::lround(linearToSrgb(v) * 255.0f));
    }
    return out;
}

void writePng(const std::string& path, const Image& image, const DisplayTransform& transform) {
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * image.height)
        fail(path, "cannot write an empty or inconsistent image");
    std::vector<glm::u8vec3> bytes(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) bytes[i] = displayColor(image.pixels[i], transform);
    writeFileAtomically(path, [&](const std::string& tmp) {
        if (!stbi_write_png(tmp.c_str(), image.width, image.height, 3, &bytes[0].x, image.width * 3))
            throw ImageError("cannot write the PNG data");
    });
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

void writeExr(const std::string& path, const ExrImage& exr, ExrPrecision precision) {
    const Image& image = exr.image;
    const size_t count = size_t(image.width) * image.height;
    if (image.width <= 0 || image.height <= 0 || image.pixels.size() != count)
        fail(path, "cannot write an empty or inconsistent image");
    if (!exr.sampleCount.empty() && exr.sampleCount.size() != count)
        fail(path, "the sample-count channel does not match the image size");
    if (!exr.sampleSums.empty() && exr.sampleSums.size() != 3 * count)
        fail(path, "the sample sums do not match the image size");

    // R, G, B (half or float), N (float), then the sums' words (32-bit unsigned), interleaved
    // per pixel in their own types.
    const OIIO::TypeDesc colour = precision == ExrPrecision::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width, image.height, 3, colour);
    spec.channelnames = {"R", "G", "B"};
    spec.channelformats = {colour, colour, colour};
    if (!exr.sampleCount.empty()) {
        spec.channelnames.push_back("N");
        spec.channelformats.push_back(OIIO::TypeDesc::FLOAT);
    }
    if (!exr.sampleSums.empty())
        for (int c = 0; c < 3; ++c)
            for (int w = 0; w < 4; ++w) {
                spec.channelnames.push_back(sumChannelName(c, w));
                spec.channelformats.push_back(OIIO::TypeDesc::UINT32);
            }
    spec.nchannels = int(spec.channelnames.size());
    spec.attribute("compression", "zip");
    if (exr.samples) {
        spec.attribute(kFirstSampleAttribute, std::to_string(exr.samples->first));
        spec.attribute(kSampleCountAttribute, std::to_string(exr.samples->count));
    }
    if (const std::optional<FrameIdentity>& f = exr.frame) {
        spec.attribute(kSceneAttribute, f->scene);
        spec.attribute(kSeedAttribute, std::to_string(f->seed));
        spec.attribute(kIntegratorAttribute, f->integrator);
        spec.attribute(kMaxDepthAttribute, f->maxDepth);
        spec.attribute(kFilterAttribute, int(f->filterWeave));
    }
    const size_t pixelBytes = spec.pixel_bytes(true);
    std::vector<unsigned char> data(count * pixelBytes);
    for (size_t i = 0; i < count; ++i) {
        unsigned char* p = &data[i * pixelBytes];
        const auto put = [&](const void* value, size_t bytes) {
            std::memcpy(p, value, bytes);
            p += bytes;
        };
        for (int c = 0; c < 3; ++c) {
            const float v = image.pixels[i][c];
            if (precision == ExrPrecision::Half) {
                const half h(v);  // Imath's, through OpenImageIO
                put(&h, sizeof h);
            } else {
                put(&v, sizeof v);
            }
        }
        if (!exr.sampleCount.empty()) put(&exr.sampleCount[i], sizeof(float));
        if (!exr.sampleSums.empty())
            for (int c = 0; c < 3; ++c) {
                const std::array<uint32_t, 4> w = exr.sampleSums[3 * i + size_t(c)].words();
                put(w.data(), sizeof w);
            }
    }
    writeFileAtomically(path, [&](const std::string& tmp) {
        // The temporary name has no .exr ending: name the plugin.
        auto out = OIIO::ImageOutput::create("openexr");
        if (!out) throw ImageError("cannot write OpenEXR: " + OIIO::geterror());
        if (!out->open(tmp, spec) || !out->write_image(OIIO::TypeUnknown, data.data()) || !out->close())
            throw ImageError("cannot write the OpenEXR data: " + out->geterror());
    });
}

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

void checkFrameFileName(const std::string& path) {
    const std::string extension = lowerExtension(path);
    if (extension != ".exr" && extension != ".png")
        fail(path, "unknown image type '" + extension + "' (expected .exr or .png)");
    checkWritable(path);
}

std::string partialFrameName(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + ".partial" + p.extension().string())).string();
}

void writeFrame(const std::string& path, const ExrImage& frame, const DisplayTransform& png) {
    checkFrameFileName(path);
    if (lowerExtension(path) == ".exr") writeExr(path, frame, ExrPrecision::Float);
    else writePng(path, frame.image, png);
}

}  // namespace woven
