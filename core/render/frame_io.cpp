#include "frame_io.h"

#include <OpenImageIO/half.h>

#include <array>
#include <cctype>
#include <charconv>
#include <cstring>
#include <filesystem>

#include "atomic_file.h"
#include "integrators.h"
#include "opened_image.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
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
    if (!hex || !isIntegratorRecord(f.integrator) ||
        f.maxDepth < 1 || (filter.get_int() != 0 && filter.get_int() != 1))
        return "has attributes " + all + " that woven does not write";
    *frame = f;
    return "";
}

}  // namespace

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
