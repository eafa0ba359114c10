#include "image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "atomic_file.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
}

std::vector<unsigned char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open the file (missing or unreadable)");
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void requireReadable(const std::string& path) {
    if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot open the file (missing or unreadable)");
}

bool hasExrMagic(const std::vector<unsigned char>& bytes) {
    return bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

std::string takeExrError(const char* err, int code) {
    std::string message = err ? err : "tinyexr error " + std::to_string(code);
    if (err) FreeEXRErrorMessage(err);
    return message;
}

// The sum channels' names, in the order ExactSum::words() gives them, R, G, B.
std::string sumChannelName(int rgb, int word) {
    return std::string("sum.") + "RGB"[rgb] + std::to_string(word);
}

// Fills `sums` from channels sum.R0-sum.B3 when the file has them; returns the problem, if any.
template <typename PlaneLookup>
std::string readSampleSums(const PlaneLookup& plane, size_t pixels, std::vector<ExactSum>* sums) {
    const uint32_t* words[3][4];
    int found = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 4; ++w) {
            words[c][w] = reinterpret_cast<const uint32_t*>(plane(sumChannelName(c, w), TINYEXR_PIXELTYPE_UINT));
            found += words[c][w] != nullptr;
        }
    if (found == 0) return "";
    if (found != 12) return "some of the 32-bit unsigned sample-sum channels sum.R0-sum.B3 are missing";
    sums->resize(3 * pixels);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            (*sums)[3 * i + size_t(c)] =
                ExactSum::fromWords({words[c][0][i], words[c][1][i], words[c][2][i], words[c][3][i]});
    return "";
}

const char* const kFirstSampleAttribute = "wovenFirstSample";
const char* const kSampleCountAttribute = "wovenSampleCount";

std::string readSampleRange(const EXRHeader& header, std::optional<SampleRange>* samples) {
    std::optional<int> first, count;
    for (int a = 0; a < header.num_custom_attributes; ++a) {
        const EXRAttribute& attribute = header.custom_attributes[a];
        std::optional<int>* target = std::strcmp(attribute.name, kFirstSampleAttribute) == 0   ? &first
                                     : std::strcmp(attribute.name, kSampleCountAttribute) == 0 ? &count
                                                                                                : nullptr;
        if (!target) continue;
        if (std::strcmp(attribute.type, "int") != 0 || attribute.size != 4)
            return std::string("attribute ") + attribute.name + " is not an int";
        int32_t value;
        std::memcpy(&value, attribute.value, 4);  // OpenEXR is little-endian, as are woven's targets
        *target = value;
    }
    if (first.has_value() != count.has_value())
        return std::string("has only one of the attributes ") + kFirstSampleAttribute + " and " + kSampleCountAttribute;
    if (first && (*first < 0 || *count < 0)) return "has a negative sample range";
    if (first) *samples = SampleRange{*first, *count};
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

Image decodeImage(const unsigned char* data, size_t size, ChannelEncoding encoding,
                  const std::string& name) {
    const int length = static_cast<int>(size);
    Image image;
    int channels = 0;
    const auto failDecode = [&]() { fail(name, std::string("cannot decode the image: ") + stbi_failure_reason()); };
    if (stbi_is_hdr_from_memory(data, length)) {
        float* pixels = stbi_loadf_from_memory(data, length, &image.width, &image.height, &channels, 3);
        if (!pixels) failDecode();
        image.pixels.resize(size_t(image.width) * image.height);
        std::memcpy(image.pixels.data(), pixels, image.pixels.size() * sizeof(glm::vec3));
        stbi_image_free(pixels);
        return image;
    }
    const auto decode = [encoding](float c) {
        return encoding == ChannelEncoding::Srgb ? srgbToLinear(c) : c;
    };
    if (stbi_is_16_bit_from_memory(data, length)) {
        stbi_us* pixels = stbi_load_16_from_memory(data, length, &image.width, &image.height, &channels, 3);
        if (!pixels) failDecode();
        image.pixels.resize(size_t(image.width) * image.height);
        for (size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) image.pixels[i][c] = decode(pixels[3 * i + c] / 65535.0f);
        stbi_image_free(pixels);
        return image;
    }
    stbi_uc* pixels = stbi_load_from_memory(data, length, &image.width, &image.height, &channels, 3);
    if (!pixels) failDecode();
    // 256-entry table: the pow() per channel would dominate loading large textures.
    std::array<float, 256> table;
    for (int v = 0; v < 256; ++v) table[v] = decode(v / 255.0f);
    image.pixels.resize(size_t(image.width) * image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = table[pixels[3 * i + c]];
    stbi_image_free(pixels);
    return image;
}

TextureImage decodeTexture(const unsigned char* data, size_t size, const std::string& name) {
    const int length = static_cast<int>(size);
    TextureImage texture;
    texture.name = name;
    int channels = 0;
    const auto failDecode = [&]() {
        const char* reason = stbi_failure_reason();
        fail(name, std::string("cannot decode the image: ") + (reason ? reason : "unknown format"));
    };
    if (stbi_is_hdr_from_memory(data, length) || stbi_is_16_bit_from_memory(data, length)) {
        const bool hdr = stbi_is_hdr_from_memory(data, length);
        float* pixels = nullptr;
        if (hdr) {
            pixels = stbi_loadf_from_memory(data, length, &texture.width, &texture.height, &channels, 4);
        } else if (stbi_us* wide = stbi_load_16_from_memory(data, length, &texture.width, &texture.height, &channels, 4)) {
            const size_t n = size_t(texture.width) * texture.height * 4;
            texture.floats.resize(n / 4);
            for (size_t i = 0; i < n; ++i) texture.floats[i / 4][int(i % 4)] = wide[i] / 65535.0f;
            stbi_image_free(wide);
            return texture;
        }
        if (!pixels) failDecode();
        texture.floats.resize(size_t(texture.width) * texture.height);
        std::memcpy(texture.floats.data(), pixels, texture.floats.size() * sizeof(glm::vec4));
        stbi_image_free(pixels);
        return texture;
    }
    stbi_uc* pixels = stbi_load_from_memory(data, length, &texture.width, &texture.height, &channels, 4);
    if (!pixels) failDecode();
    texture.bytes.resize(size_t(texture.width) * texture.height);
    std::memcpy(texture.bytes.data(), pixels, texture.bytes.size() * sizeof(glm::u8vec4));
    stbi_image_free(pixels);
    return texture;
}

ExrImage readExr(const std::string& path) {
    requireReadable(path);
    EXRVersion version;
    int code = ParseEXRVersionFromFile(&version, path.c_str());
    if (code != TINYEXR_SUCCESS) fail(path, "not an OpenEXR file (bad magic number or version)");
    if (version.multipart) fail(path, "multi-part OpenEXR files are not supported");

    EXRHeader header;
    InitEXRHeader(&header);
    const char* err = nullptr;
    code = ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err);
    if (code != TINYEXR_SUCCESS) fail(path, "cannot read the OpenEXR header: " + takeExrError(err, code));
    for (int c = 0; c < header.num_channels; ++c)
        if (header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
            header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;

    EXRImage loaded;
    InitEXRImage(&loaded);
    code = LoadEXRImageFromFile(&loaded, &header, path.c_str(), &err);
    if (code != TINYEXR_SUCCESS) {
        FreeEXRHeader(&header);
        fail(path, "cannot decode the OpenEXR image: " + takeExrError(err, code));
    }

    ExrImage result;
    std::string problem;
    if (!loaded.images) problem = "tiled OpenEXR files are not supported";
    const auto plane = [&](const std::string& name, int type) -> const unsigned char* {
        for (int c = 0; c < header.num_channels; ++c)
            if (header.channels[c].name == name && header.requested_pixel_types[c] == type) return loaded.images[c];
        return nullptr;
    };
    const auto channel = [&](const char* name) {
        return reinterpret_cast<const float*>(plane(name, TINYEXR_PIXELTYPE_FLOAT));
    };
    if (problem.empty()) {
        const float* r = channel("R");
        const float* g = channel("G");
        const float* b = channel("B");
        const float* y = channel("Y");
        if (!(r && g && b) && y) r = g = b = y;
        if (!(r && g && b)) problem = "no float or half R, G, B (or Y) channels";
        else {
            Image& image = result.image;
            image.width = loaded.width;
            image.height = loaded.height;
            image.pixels.resize(size_t(image.width) * image.height);
            for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = {r[i], g[i], b[i]};
            if (const float* n = channel("N")) result.sampleCount.assign(n, n + image.pixels.size());
            problem = readSampleSums(plane, image.pixels.size(), &result.sampleSums);
            if (problem.empty()) problem = readSampleRange(header, &result.samples);
        }
    }
    FreeEXRImage(&loaded);
    FreeEXRHeader(&header);
    if (!problem.empty()) fail(path, problem);
    return result;
}

Image readImage(const std::string& path, ChannelEncoding encoding) {
    const std::vector<unsigned char> bytes = readBytes(path);
    if (hasExrMagic(bytes)) return readExr(path).image;
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

    // Channels in alphabetical order, as OpenEXR readers expect: B, G, (N,) R.
    std::vector<std::vector<float>> planes(3, std::vector<float>(count));
    for (size_t i = 0; i < count; ++i) {
        planes[0][i] = image.pixels[i].b;
        planes[1][i] = image.pixels[i].g;
        planes[2][i] = image.pixels[i].r;
    }
    std::vector<std::string> names = {"B", "G", "R"};
    const int colorType = precision == ExrPrecision::Half ? TINYEXR_PIXELTYPE_HALF : TINYEXR_PIXELTYPE_FLOAT;
    std::vector<int> requested(3, colorType);
    if (!exr.sampleCount.empty()) {
        planes.insert(planes.begin() + 2, exr.sampleCount);
        names.insert(names.begin() + 2, "N");
        requested.insert(requested.begin() + 2, TINYEXR_PIXELTYPE_FLOAT);
    }
    std::vector<int> inputTypes(planes.size(), TINYEXR_PIXELTYPE_FLOAT);
    std::vector<unsigned char*> pointers;
    for (std::vector<float>& p : planes) pointers.push_back(reinterpret_cast<unsigned char*>(p.data()));
    // After R in the alphabet: sum.B0 ... sum.R3.
    std::vector<std::vector<uint32_t>> sumPlanes;
    if (!exr.sampleSums.empty()) {
        if (exr.sampleSums.size() != 3 * count) fail(path, "the sample sums do not match the image size");
        for (int c : {2, 1, 0}) {
            std::vector<std::vector<uint32_t>> words(4, std::vector<uint32_t>(count));
            for (size_t i = 0; i < count; ++i) {
                const std::array<uint32_t, 4> w = exr.sampleSums[3 * i + size_t(c)].words();
                for (size_t k = 0; k < 4; ++k) words[k][i] = w[k];
            }
            for (int k = 0; k < 4; ++k) {
                sumPlanes.push_back(std::move(words[size_t(k)]));
                names.push_back(sumChannelName(c, k));
                requested.push_back(TINYEXR_PIXELTYPE_UINT);
                inputTypes.push_back(TINYEXR_PIXELTYPE_UINT);
            }
        }
        for (std::vector<uint32_t>& p : sumPlanes) pointers.push_back(reinterpret_cast<unsigned char*>(p.data()));
    }
    const int channels = int(pointers.size());
    std::vector<EXRChannelInfo> infos(channels);
    for (int c = 0; c < channels; ++c) {
        std::memset(&infos[c], 0, sizeof(EXRChannelInfo));
        std::strncpy(infos[c].name, names[c].c_str(), sizeof(infos[c].name) - 1);
    }

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.num_channels = channels;
    exrImage.images = pointers.data();
    exrImage.width = image.width;
    exrImage.height = image.height;

    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = channels;
    header.channels = infos.data();
    header.pixel_types = inputTypes.data();
    header.requested_pixel_types = requested.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    int32_t rangeValues[2] = {0, 0};
    EXRAttribute rangeAttributes[2];
    if (exr.samples) {
        rangeValues[0] = exr.samples->first;
        rangeValues[1] = exr.samples->count;
        const char* const attributeNames[2] = {kFirstSampleAttribute, kSampleCountAttribute};
        for (int a = 0; a < 2; ++a) {
            std::memset(&rangeAttributes[a], 0, sizeof(EXRAttribute));
            std::strncpy(rangeAttributes[a].name, attributeNames[a], sizeof(rangeAttributes[a].name) - 1);
            std::strncpy(rangeAttributes[a].type, "int", sizeof(rangeAttributes[a].type) - 1);
            rangeAttributes[a].value = reinterpret_cast<unsigned char*>(&rangeValues[a]);
            rangeAttributes[a].size = 4;
        }
        header.custom_attributes = rangeAttributes;
        header.num_custom_attributes = 2;
    }

    writeFileAtomically(path, [&](const std::string& tmp) {
        const char* err = nullptr;
        const int code = SaveEXRImageToFile(&exrImage, &header, tmp.c_str(), &err);
        if (code != TINYEXR_SUCCESS) throw ImageError("cannot write the OpenEXR data: " + takeExrError(err, code));
    });
}

namespace {
std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}
}  // namespace

void checkFrameFileName(const std::string& path) {
    const std::string extension = lowerExtension(path);
    if (extension != ".exr" && extension != ".png")
        fail(path, "unknown image type '" + extension + "' (expected .exr or .png)");
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
