#include "frame_io.h"

#include <OpenImageIO/half.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstring>
#include <filesystem>

#include "output_path.h"
#include "integrators.h"
#include "opened_image.h"
#include "sampler.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw ImageError(path + ": " + problem);
}

// Files of earlier versions kept the radiance sums as 32-bit unsigned words, sum.R0-sum.B3 in
// ExactSum::words()' order; merge still reads them.
std::string oldSumChannelName(int rgb, int word) {
    return std::string("sum.") + "RGB"[rgb] + std::to_string(word);
}

// The exact sums a frame file keeps, each as ExactSum::kFloatWords float channels
// exact.NAMEk.C (k = 0 the least significant word): the radiance and the render passes'.
struct ExactGroup {
    const char* name;
    const char* channels;
};
constexpr ExactGroup kExactGroups[] = {
    {"radiance", "RGB"}, {"albedo", "RGB"}, {"normal", "XYZ"}, {"depth", "Z"}, {"square", "RGB"},
    {"direct", "RGB"}, {"directSquare", "Y"},
};
constexpr int kRadianceGroup = 0;
// Frames of versions before the direct-light pass lack its two groups, the last; they are read
// with it 0.
constexpr int kDirectGroup = 5, kDirectGroups = 2;

std::string exactChannelName(const ExactGroup& g, int word, int c) {
    return std::string("exact.") + g.name + std::to_string(word) + "." + g.channels[c];
}

// The sum of group g, channel c, at pixel i.
template <class Frame>
auto& exactSum(Frame& exr, int g, size_t i, int c) {
    switch (g) {
        case 0: return exr.sampleSums[3 * i + size_t(c)];
        case 1: return exr.passSums[i].albedo[c];
        case 2: return exr.passSums[i].normal[c];
        case 3: return exr.passSums[i].depth;
        case 4: return exr.passSums[i].square[c];
        case 5: return exr.passSums[i].direct[c];
        default: return exr.passSums[i].directSquare;
    }
}

// The visible layers of the render passes, as compositors name them.
struct PassLayer {
    const char* name;
    const char* channels;
};
constexpr PassLayer kPassLayers[] = {
    {"albedo", "RGB"}, {"normal", "XYZ"}, {"depth", "Z"}, {"variance", "RGB"}, {"direct", "RGB"}};

float passValue(const RenderPasses& p, int layer, size_t i, int c) {
    switch (layer) {
        case 0: return p.albedo.pixels[i][c];
        case 1: return p.normal.pixels[i][c];
        case 2: return p.depth[i];
        case 3: return p.variance.pixels[i][c];
        default: return p.direct.pixels[i][c];
    }
}

const char* const kCountChannel = "samples.N";
const char* const kOldCountChannel = "N";  // files of earlier versions

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
const char* const kSamplerAttribute = "wovenSampler";  // not in frames of woven before it recorded it

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
    if (const OIIO::ParamValue* sampler = spec.find_attribute(kSamplerAttribute)) {
        if (sampler->type() != OIIO::TypeString) return "the attribute wovenSampler must be a string";
        f.sampler = sampler->get_string();
        if (std::find(std::begin(kSamplerNames), std::end(kSamplerNames), f.sampler) == std::end(kSamplerNames))
            return "has the attribute wovenSampler \"" + f.sampler + "\", a sampler woven does not have";
    }
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
    // Every channel in its own type: older files' sums are 32-bit unsigned words, which floats
    // would round.
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
    const size_t count = size_t(spec.width) * size_t(spec.height);
    // An RGB layer ("" for the beauty), or none when the file lacks any of its channels.
    const auto readRgb = [&](const std::string& prefix, Image* image) {
        const int r = find(prefix + "R"), g = find(prefix + "G"), b = find(prefix + "B");
        if (r < 0 || g < 0 || b < 0) return false;
        image->width = spec.width;
        image->height = spec.height;
        image->pixels.resize(count);
        for (size_t i = 0; i < count; ++i) image->pixels[i] = {asFloat(r, i), asFloat(g, i), asFloat(b, i)};
        return true;
    };
    ExrImage result;
    if (!readRgb("", &result.image)) {
        const int y = find("Y");
        if (y < 0) fail(path, "no R, G, B (or Y) channels");
        result.image.width = spec.width;
        result.image.height = spec.height;
        result.image.pixels.resize(count);
        for (size_t i = 0; i < count; ++i) result.image.pixels[i] = glm::vec3(asFloat(y, i));
    }
    if (Image noisy; readRgb("noisy.", &noisy)) result.noisy = std::move(noisy);
    int n = find(kCountChannel);
    if (n < 0) n = find(kOldCountChannel);
    if (n >= 0) {
        result.sampleCount.resize(count);
        for (size_t i = 0; i < count; ++i) result.sampleCount[i] = asFloat(n, i);
    }

    int oldWords[3][4], oldFound = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 4; ++w) {
            oldWords[c][w] = find(oldSumChannelName(c, w));
            if (oldWords[c][w] >= 0 && spec.channelformat(oldWords[c][w]) != OIIO::TypeDesc::UINT32)
                fail(path, "the sample-sum channel " + oldSumChannelName(c, w) + " is not 32-bit unsigned");
            oldFound += oldWords[c][w] >= 0;
        }
    if (oldFound != 0 && oldFound != 12) fail(path, "some of the 32-bit unsigned sample-sum channels sum.R0-sum.B3 are missing");
    if (oldFound == 12) {
        result.sampleSums.resize(3 * count);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) {
                std::array<uint32_t, 4> w{};
                for (int k = 0; k < 4; ++k)
                    std::memcpy(&w[size_t(k)], &raw[i * pixelBytes + offset[size_t(oldWords[c][k])]], 4);
                result.sampleSums[3 * i + size_t(c)] = ExactSum::fromWords(w);
            }
    }

    // The exact sums: each group all there or not at all; the passes' only with the radiance's.
    std::vector<int> words[std::size(kExactGroups)];
    bool groupFound[std::size(kExactGroups)] = {};
    int groupsFound = 0;
    for (size_t g = 0; g < std::size(kExactGroups); ++g) {
        const ExactGroup& group = kExactGroups[g];
        const int channels = int(std::strlen(group.channels));
        for (int w = 0; w < ExactSum::kFloatWords; ++w)
            for (int c = 0; c < channels; ++c) words[g].push_back(find(exactChannelName(group, w, c)));
        const size_t found = size_t(std::count_if(words[g].begin(), words[g].end(), [](int c) { return c >= 0; }));
        if (found != 0 && found != words[g].size())
            fail(path, std::string("some of the exact-sum channels exact.") + group.name + "0." + group.channels[0] + "-exact." +
                           group.name + std::to_string(ExactSum::kFloatWords - 1) + "." + group.channels[channels - 1] +
                           " are missing");
        groupFound[g] = found != 0;
        if (found != 0) ++groupsFound;
    }
    const bool exactRadiance = !words[kRadianceGroup].empty() && words[kRadianceGroup].front() >= 0;
    if (exactRadiance && oldFound != 0) fail(path, "has both the exact sums exact.radiance* and the older sum.R0-sum.B3");
    const int passGroupsFound = groupsFound - int(groupFound[kRadianceGroup]);
    const int passGroupsNeeded = int(std::size(kExactGroups)) - 1 - (groupFound[kDirectGroup] ? 0 : kDirectGroups);
    if (passGroupsFound != 0 && passGroupsFound != passGroupsNeeded)
        fail(path, "has the exact sums of some render passes but not of all (exact.albedo*, exact.normal*, exact.depth*, "
                   "exact.square*)");
    if (groupsFound != 0 && !exactRadiance) fail(path, "has the render passes' exact sums without the radiance's (exact.radiance*)");
    if (groupsFound != 0) {
        result.sampleSums.resize(3 * count);
        if (groupsFound > 1) {
            result.passSums.resize(count);
            result.lacksDirectPass = !groupFound[kDirectGroup];
        }
        for (int g = 0; g < int(std::size(kExactGroups)); ++g) {
            if (!groupFound[g]) continue;
            const ExactGroup& group = kExactGroups[g];
            const int channels = int(std::strlen(group.channels));
            for (size_t i = 0; i < count; ++i)
                for (int c = 0; c < channels; ++c) {
                    std::array<float, ExactSum::kFloatWords> w{};
                    for (int k = 0; k < ExactSum::kFloatWords; ++k) w[size_t(k)] = asFloat(words[g][size_t(k * channels + c)], i);
                    const std::optional<ExactSum> sum = ExactSum::fromFloatWords(w);
                    if (!sum)
                        fail(path, "pixel (" + std::to_string(i % size_t(spec.width)) + ", " + std::to_string(i / size_t(spec.width)) +
                                       ") of the exact-sum channels exact." + group.name + "0-5." + group.channels[c] +
                                       " holds a word that is not a whole number below 2^24 (the top word below 2^8)");
                    exactSum(result, g, i, c) = *sum;
                }
        }
    }
    if (!result.sampleSums.empty() && result.sampleCount.empty()) fail(path, "has exact sums but no sample-count channel samples.N");
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
    if (!exr.passSums.empty() && (exr.passSums.size() != count || exr.sampleSums.empty() || exr.sampleCount.empty()))
        fail(path, "the render passes' sums do not match the image size, or come without sample counts and sums");
    if (exr.noisy && (exr.noisy->width != image.width || exr.noisy->height != image.height || exr.noisy->pixels.size() != count))
        fail(path, "the noisy beauty does not match the image size");
    // A plain value and a flag, not an optional: GCC 12 warns of the optional's vectors as maybe
    // uninitialised where the layers are read.
    const bool hasPasses = !exr.passSums.empty();
    const RenderPasses passes = hasPasses ? exr.passes() : RenderPasses{};

    // Every channel half or float with a name of layer.pass.channel form (or R, G, B), so that
    // compositors (Blender, Nuke) read the file as a multi-layer image: the beauty and the passes
    // in `precision`, the count and the exact sums' words in float. Interleaved per pixel.
    const OIIO::TypeDesc colour = precision == ExrPrecision::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(image.width, image.height, 0, colour);
    spec.channelnames.clear();
    spec.channelformats.clear();
    const auto channel = [&](const std::string& name, OIIO::TypeDesc type) {
        spec.channelnames.push_back(name);
        spec.channelformats.push_back(type);
    };
    for (const char* c : {"R", "G", "B"}) channel(c, colour);
    if (exr.noisy)
        for (const char* c : {"R", "G", "B"}) channel(std::string("noisy.") + c, colour);
    // The direct-light pass is last among the layers and the exact groups: a file of an older
    // woven, read and written again, goes without it.
    const int passLayers = int(std::size(kPassLayers)) - int(exr.lacksDirectPass);
    if (hasPasses)
        for (int l = 0; l < passLayers; ++l)
            for (const char* c = kPassLayers[l].channels; *c; ++c) channel(std::string(kPassLayers[l].name) + "." + *c, colour);
    if (!exr.sampleCount.empty()) channel(kCountChannel, OIIO::TypeDesc::FLOAT);
    const int exactGroups =
        hasPasses ? int(std::size(kExactGroups)) - (exr.lacksDirectPass ? kDirectGroups : 0) : exr.sampleSums.empty() ? 0 : 1;
    for (int g = 0; g < exactGroups; ++g)
        for (int w = 0; w < ExactSum::kFloatWords; ++w)
            for (int c = 0; c < int(std::strlen(kExactGroups[g].channels)); ++c)
                channel(exactChannelName(kExactGroups[g], w, c), OIIO::TypeDesc::FLOAT);
    spec.nchannels = int(spec.channelnames.size());
    // RLE: of a 640x480 frame's 95 channels, ZIP took 4.2 s to write on the 2-core VM for 38 MB,
    // RLE 0.7 s for 50 MB (PIZ 2.1 s, 50 MB): the render, not the file, should take the time.
    spec.attribute("compression", "rle");
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
        if (!f->sampler.empty()) spec.attribute(kSamplerAttribute, f->sampler);
    }
    const size_t pixelBytes = spec.pixel_bytes(true);
    std::vector<unsigned char> data(count * pixelBytes);
    for (size_t i = 0; i < count; ++i) {
        unsigned char* p = &data[i * pixelBytes];
        const auto put = [&](float v, OIIO::TypeDesc type) {
            if (type == OIIO::TypeDesc::HALF) {
                const half h(v);  // Imath's, through OpenImageIO
                std::memcpy(p, &h, sizeof h);
                p += sizeof h;
            } else {
                std::memcpy(p, &v, sizeof v);
                p += sizeof v;
            }
        };
        for (int c = 0; c < 3; ++c) put(image.pixels[i][c], colour);
        if (exr.noisy)
            for (int c = 0; c < 3; ++c) put(exr.noisy->pixels[i][c], colour);
        if (hasPasses)
            for (int l = 0; l < passLayers; ++l)
                for (int c = 0; c < int(std::strlen(kPassLayers[l].channels)); ++c) put(passValue(passes, l, i, c), colour);
        if (!exr.sampleCount.empty()) put(exr.sampleCount[i], OIIO::TypeDesc::FLOAT);
        for (int g = 0; g < exactGroups; ++g) {
            const int channels = int(std::strlen(kExactGroups[g].channels));
            std::array<float, ExactSum::kFloatWords> w[3];
            for (int c = 0; c < channels; ++c) w[c] = exactSum(exr, g, i, c).floatWords();
            for (int k = 0; k < ExactSum::kFloatWords; ++k)
                for (int c = 0; c < channels; ++c) put(w[c][size_t(k)], OIIO::TypeDesc::FLOAT);
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
    checkOutput(path);
}

void writeFrame(const std::string& path, const ExrImage& frame, const DisplayTransform& png) {
    checkFrameFileName(path);
    if (lowerExtension(path) == ".exr") writeExr(path, frame, ExrPrecision::Float);
    else writePng(path, frame.image, png);
}

}  // namespace woven
