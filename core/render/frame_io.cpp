#include "frame_io.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "exr_file.h"
#include "image_checks.h"
#include "output_path.h"
#include "integrators.h"
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

using Attributes = std::map<std::string, ExrAttribute>;

const ExrAttribute* findAttribute(const Attributes& attributes, const char* name) {
    const auto found = attributes.find(name);
    return found == attributes.end() ? nullptr : &found->second;
}

// A sample index: a decimal string, or an int as versions before 64-bit ranges wrote it.
bool readSampleIndex(const ExrAttribute& value, int64_t* index) {
    if (const int* i = std::get_if<int>(&value)) {
        *index = *i;
        return true;
    }
    const std::string* text = std::get_if<std::string>(&value);
    return text && parseWhole(*text, index);
}

std::string readSampleRange(const Attributes& attributes, std::optional<SampleRange>* samples) {
    const ExrAttribute* first = findAttribute(attributes, kFirstSampleAttribute);
    const ExrAttribute* count = findAttribute(attributes, kSampleCountAttribute);
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

std::string readFrameIdentity(const Attributes& attributes, std::optional<FrameIdentity>* frame) {
    const char* const names[] = {kSceneAttribute, kSeedAttribute, kIntegratorAttribute, kMaxDepthAttribute, kFilterAttribute};
    int found = 0;
    for (const char* name : names) found += findAttribute(attributes, name) != nullptr;
    if (found == 0) return "";
    const std::string all = "wovenScene, wovenSeed, wovenIntegrator, wovenMaxDepth and wovenFilter";
    if (found != 5) return "has only some of the attributes " + all;
    const std::string* scene = std::get_if<std::string>(findAttribute(attributes, kSceneAttribute));
    const std::string* seed = std::get_if<std::string>(findAttribute(attributes, kSeedAttribute));
    const std::string* integrator = std::get_if<std::string>(findAttribute(attributes, kIntegratorAttribute));
    const int* maxDepth = std::get_if<int>(findAttribute(attributes, kMaxDepthAttribute));
    const int* filter = std::get_if<int>(findAttribute(attributes, kFilterAttribute));
    FrameIdentity f;
    if (!scene || !seed || !integrator || !maxDepth || !filter || !parseWhole(*seed, &f.seed))
        return "the attributes " + all + " must be a string, a decimal string, a string and two ints";
    f.scene = *scene;
    f.integrator = *integrator;
    f.maxDepth = *maxDepth;
    f.filterWeave = *filter != 0;
    if (const ExrAttribute* sampler = findAttribute(attributes, kSamplerAttribute)) {
        const std::string* name = std::get_if<std::string>(sampler);
        if (!name) return "the attribute wovenSampler must be a string";
        f.sampler = *name;
        if (std::find(std::begin(kSamplerNames), std::end(kSamplerNames), f.sampler) == std::end(kSamplerNames))
            return "has the attribute wovenSampler \"" + f.sampler + "\", a sampler woven does not have";
    }
    // Merge names them in its messages: only what woven writes.
    const bool hex = f.scene.size() == 16 && f.scene.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!hex || !isIntegratorRecord(f.integrator) ||
        f.maxDepth < 1 || (*filter != 0 && *filter != 1))
        return "has attributes " + all + " that woven does not write";
    *frame = f;
    return "";
}

// Every channel as stored: older files' sums are 32-bit unsigned words, which floats would
// round; the count and the exact sums' words are whole floats.
float asFloat(const ExrChannel* c, size_t i) {
    return c->type == ExrChannelType::Uint ? float(c->words[i]) : c->values[i];
}

// An RGB layer ("" for the beauty), or false when the file lacks any of its channels.
bool readRgb(const ExrFile& file, const std::string& prefix, Image* image) {
    const ExrChannel *r = file.channel(prefix + "R"), *g = file.channel(prefix + "G"), *b = file.channel(prefix + "B");
    if (!r || !g || !b) return false;
    const size_t count = size_t(file.width) * size_t(file.height);
    image->width = file.width;
    image->height = file.height;
    image->pixels.resize(count);
    for (size_t i = 0; i < count; ++i) image->pixels[i] = {asFloat(r, i), asFloat(g, i), asFloat(b, i)};
    return true;
}

// The beauty (RGB, or grey Y), the noisy beauty where there is one, and the sample counts.
void readImages(const ExrFile& file, const std::string& path, ExrImage* result) {
    const size_t count = size_t(file.width) * size_t(file.height);
    if (!readRgb(file, "", &result->image)) {
        const ExrChannel* y = file.channel("Y");
        if (!y) fail(path, "no R, G, B (or Y) channels");
        result->image.width = file.width;
        result->image.height = file.height;
        result->image.pixels.resize(count);
        for (size_t i = 0; i < count; ++i) result->image.pixels[i] = glm::vec3(asFloat(y, i));
    }
    if (Image noisy; readRgb(file, "noisy.", &noisy)) result->noisy = std::move(noisy);
    const ExrChannel* n = file.channel(kCountChannel);
    if (!n) n = file.channel(kOldCountChannel);
    if (n) {
        result->sampleCount.resize(count);
        for (size_t i = 0; i < count; ++i) result->sampleCount[i] = asFloat(n, i);
    }
}

// The radiance sums as files of earlier versions kept them, all twelve words or none; returns
// how many of their channels the file has.
int readOldSums(const ExrFile& file, const std::string& path, ExrImage* result) {
    const size_t count = size_t(file.width) * size_t(file.height);
    const ExrChannel* oldWords[3][4];
    int oldFound = 0;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 4; ++w) {
            oldWords[c][w] = file.channel(oldSumChannelName(c, w));
            if (oldWords[c][w] && oldWords[c][w]->type != ExrChannelType::Uint)
                fail(path, "the sample-sum channel " + oldSumChannelName(c, w) + " is not 32-bit unsigned");
            oldFound += oldWords[c][w] != nullptr;
        }
    if (oldFound != 0 && oldFound != 12) fail(path, "some of the 32-bit unsigned sample-sum channels sum.R0-sum.B3 are missing");
    if (oldFound == 12) {
        result->sampleSums.resize(3 * count);
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) {
                std::array<uint32_t, 4> w{};
                for (int k = 0; k < 4; ++k) w[size_t(k)] = oldWords[c][k]->words[i];
                result->sampleSums[3 * i + size_t(c)] = ExactSum::fromWords(w);
            }
    }
    return oldFound;
}

// The exact sums' channels of group g in the order of ExactSum's words, channel by channel, each
// null where the file lacks it; fails when only some are there.
std::vector<const ExrChannel*> exactChannels(const ExrFile& file, const std::string& path, size_t g) {
    const ExactGroup& group = kExactGroups[g];
    const int channels = int(std::strlen(group.channels));
    std::vector<const ExrChannel*> words;
    for (int w = 0; w < ExactSum::kFloatWords; ++w)
        for (int c = 0; c < channels; ++c) words.push_back(file.channel(exactChannelName(group, w, c)));
    const size_t found = size_t(std::count_if(words.begin(), words.end(), [](const ExrChannel* c) { return c; }));
    if (found != 0 && found != words.size())
        fail(path, std::string("some of the exact-sum channels exact.") + group.name + "0." + group.channels[0] + "-exact." +
                       group.name + std::to_string(ExactSum::kFloatWords - 1) + "." + group.channels[channels - 1] +
                       " are missing");
    return words;
}

// Group g's sums at every pixel from its channels' words.
void readExactGroup(const ExrFile& file, const std::string& path, int g, const std::vector<const ExrChannel*>& words,
                    ExrImage* result) {
    const size_t count = size_t(file.width) * size_t(file.height);
    const ExactGroup& group = kExactGroups[g];
    const int channels = int(std::strlen(group.channels));
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c) {
            std::array<float, ExactSum::kFloatWords> w{};
            for (int k = 0; k < ExactSum::kFloatWords; ++k) w[size_t(k)] = asFloat(words[size_t(k * channels + c)], i);
            const std::optional<ExactSum> sum = ExactSum::fromFloatWords(w);
            if (!sum)
                fail(path, "pixel (" + std::to_string(i % size_t(file.width)) + ", " + std::to_string(i / size_t(file.width)) +
                               ") of the exact-sum channels exact." + group.name + "0-5." + group.channels[c] +
                               " holds a word that is not a whole number below 2^24 (the top word below 2^8)");
            exactSum(*result, g, i, c) = *sum;
        }
}

// The exact sums: each group all there or not at all; the passes' only with the radiance's, and
// not beside the older sums (oldSums).
void readExactSums(const ExrFile& file, const std::string& path, bool oldSums, ExrImage* result) {
    std::vector<const ExrChannel*> words[std::size(kExactGroups)];
    bool groupFound[std::size(kExactGroups)] = {};
    int groupsFound = 0;
    for (size_t g = 0; g < std::size(kExactGroups); ++g) {
        words[g] = exactChannels(file, path, g);
        groupFound[g] = words[g].front() != nullptr;
        if (groupFound[g]) ++groupsFound;
    }
    const bool exactRadiance = groupFound[kRadianceGroup];
    if (exactRadiance && oldSums) fail(path, "has both the exact sums exact.radiance* and the older sum.R0-sum.B3");
    const int passGroupsFound = groupsFound - int(groupFound[kRadianceGroup]);
    const int passGroupsNeeded = int(std::size(kExactGroups)) - 1 - (groupFound[kDirectGroup] ? 0 : kDirectGroups);
    if (passGroupsFound != 0 && passGroupsFound != passGroupsNeeded)
        fail(path, "has the exact sums of some render passes but not of all (exact.albedo*, exact.normal*, exact.depth*, "
                   "exact.square*)");
    if (groupsFound != 0 && !exactRadiance) fail(path, "has the render passes' exact sums without the radiance's (exact.radiance*)");
    if (groupsFound == 0) return;
    const size_t count = size_t(file.width) * size_t(file.height);
    result->sampleSums.resize(3 * count);
    if (groupsFound > 1) {
        result->passSums.resize(count);
        result->lacksDirectPass = !groupFound[kDirectGroup];
    }
    for (int g = 0; g < int(std::size(kExactGroups)); ++g)
        if (groupFound[g]) readExactGroup(file, path, g, words[g], result);
}

// Now as OpenEXR's standard attribute capDate has it ("YYYY:MM:DD hh:mm:ss", local time), which
// frames of woven have carried since OpenImageIO wrote them.
std::string writtenAt() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
    return text;
}

}  // namespace

ExrImage readExr(const std::string& path) {
    const std::vector<unsigned char> bytes = readImageFile(path);
    const ExrFile file = readExrFile(bytes.data(), bytes.size(), path);
    ExrImage result;
    readImages(file, path, &result);
    const int oldFound = readOldSums(file, path, &result);
    readExactSums(file, path, oldFound != 0, &result);
    if (!result.sampleSums.empty() && result.sampleCount.empty()) fail(path, "has exact sums but no sample-count channel samples.N");
    if (const std::string problem = readSampleRange(file.attributes, &result.samples); !problem.empty()) fail(path, problem);
    if (const std::string problem = readFrameIdentity(file.attributes, &result.frame); !problem.empty()) fail(path, problem);
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
    // in `precision`, the count and the exact sums' words in float.
    const ExrChannelType colour = precision == ExrPrecision::Half ? ExrChannelType::Half : ExrChannelType::Float;
    ExrFile file;
    file.width = image.width;
    file.height = image.height;
    const auto channel = [&](const std::string& name, ExrChannelType type) -> std::vector<float>& {
        ExrChannel& c = file.channels.emplace_back();
        c.name = name;
        c.type = type;
        c.values.resize(count);
        return c.values;
    };
    const auto rgb = [&](const std::string& prefix, const Image& from) {
        for (int c = 0; c < 3; ++c) {
            std::vector<float>& values = channel(prefix + "RGB"[c], colour);
            for (size_t i = 0; i < count; ++i) values[i] = from.pixels[i][c];
        }
    };
    rgb("", image);
    if (exr.noisy) rgb("noisy.", *exr.noisy);
    // The direct-light pass is last among the layers and the exact groups: a file of an older
    // woven, read and written again, goes without it.
    const int passLayers = int(std::size(kPassLayers)) - int(exr.lacksDirectPass);
    if (hasPasses)
        for (int l = 0; l < passLayers; ++l)
            for (int c = 0; kPassLayers[l].channels[c]; ++c) {
                std::vector<float>& values = channel(std::string(kPassLayers[l].name) + "." + kPassLayers[l].channels[c], colour);
                for (size_t i = 0; i < count; ++i) values[i] = passValue(passes, l, i, c);
            }
    if (!exr.sampleCount.empty()) channel(kCountChannel, ExrChannelType::Float) = exr.sampleCount;
    const int exactGroups =
        hasPasses ? int(std::size(kExactGroups)) - (exr.lacksDirectPass ? kDirectGroups : 0) : exr.sampleSums.empty() ? 0 : 1;
    for (int g = 0; g < exactGroups; ++g)
        for (int c = 0; kExactGroups[g].channels[c]; ++c) {
            // The words' channels are the last kFloatWords added (a reference to one would not
            // survive adding the next).
            for (int k = 0; k < ExactSum::kFloatWords; ++k) channel(exactChannelName(kExactGroups[g], k, c), ExrChannelType::Float);
            ExrChannel* words = &file.channels[file.channels.size() - ExactSum::kFloatWords];
            for (size_t i = 0; i < count; ++i) {
                const std::array<float, ExactSum::kFloatWords> w = exactSum(exr, g, i, c).floatWords();
                for (int k = 0; k < ExactSum::kFloatWords; ++k) words[k].values[i] = w[size_t(k)];
            }
        }
    if (exr.samples) {
        file.attributes[kFirstSampleAttribute] = std::to_string(exr.samples->first);
        file.attributes[kSampleCountAttribute] = std::to_string(exr.samples->count);
    }
    if (const std::optional<FrameIdentity>& f = exr.frame) {
        file.attributes[kSceneAttribute] = f->scene;
        file.attributes[kSeedAttribute] = std::to_string(f->seed);
        file.attributes[kIntegratorAttribute] = f->integrator;
        file.attributes[kMaxDepthAttribute] = f->maxDepth;
        file.attributes[kFilterAttribute] = int(f->filterWeave);
        if (!f->sampler.empty()) file.attributes[kSamplerAttribute] = f->sampler;
    }
    file.attributes["capDate"] = writtenAt();
    writeExrFile(path, file);
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
