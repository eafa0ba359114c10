// `woven merge`: combine EXR renders of disjoint sample ranges of one frame (for example the
// tasks of a Slurm job array, see `woven submit`) into the render of their union. Each part
// keeps the exact sums of its samples and its sample range (image_io.h), so the merge is the
// frame one render of the union gives, bit for bit, and overlaps and gaps are seen. Parts also
// record which frame they are of (frame_identity.h): parts of different frames are refused.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "commands.h"
#include "atomic_file.h"
#include "frame_denoise.h"
#include "frame_io.h"
#include "image_io.h"
#include "integrators.h"
#include "number_checks.h"
#include "output_path.h"
#include "short_number.h"

namespace woven {

namespace {

struct Part {
    std::string path;
    SampleRange samples;
    std::optional<FrameIdentity> frame;
};

ExrImage readPart(const std::string& path) {
    ExrImage part = readExr(path);
    const auto missing = [&](const std::string& what) {
        return std::invalid_argument(path + ": has no " + what +
                                     ": merge takes the EXR files of woven render (-o FILE.exr)");
    };
    if (part.sampleCount.empty()) throw missing("sample-count channel samples.N");
    if (part.sampleSums.empty()) throw missing("exact sample sums (channels exact.radiance0.R-exact.radiance5.B)");
    if (!part.samples) throw missing("sample range (attributes wovenFirstSample, wovenSampleCount)");
    // A count is what the sums are divided by: NaN or a negative one would write NaN or negate
    // the pixel, one past the part's samples would darken it, and 0 beside a sum other parts'
    // counts would divide (the pixel twice as bright). Each is a whole number of the part's range.
    const double most = double(part.samples->count);
    for (size_t i = 0; i < part.sampleCount.size(); ++i) {
        const float n = part.sampleCount[i];
        const std::string pixel = path + ": pixel (" + std::to_string(i % size_t(part.image.width)) + ", " +
                                  std::to_string(i / size_t(part.image.width)) + ") has the sample count N = " + shortNumber(n);
        if (!(n >= 0.0f && n <= most && std::floor(n) == n))
            throw std::invalid_argument(pixel + ", which is not a whole number from 0 to the part's " + shortNumber(most) +
                                        " samples (" + describe(*part.samples) + ")");
        if (n == 0.0f)
            for (size_t c = 3 * i; c < 3 * i + 3 && c < part.sampleSums.size(); ++c)
                if (part.sampleSums[c] != ExactSum())
                    throw std::invalid_argument(pixel + " beside a radiance sum that is not 0: no sample made that sum");
    }
    return part;
}

// Throws when parts (sorted by their first sample) overlap, or fall outside [0, expected).
void checkDisjoint(const std::vector<Part>& sorted, std::optional<int64_t> expected) {
    for (size_t i = 1; i < sorted.size(); ++i) {
        const Part &a = sorted[i - 1], &b = sorted[i];
        if (b.samples.first < a.samples.end())
            throw std::invalid_argument(a.path + " (" + describe(a.samples) + ") and " + b.path + " (" +
                                        describe(b.samples) + ") overlap: samples would count twice");
    }
    for (const Part& p : sorted)
        if (expected && p.samples.end() > *expected)
            throw std::invalid_argument(p.path + " holds " + describe(p.samples) + ", beyond the " +
                                        std::to_string(*expected) + " expected");
}

// How `b`'s identity keeps it out of `a`'s frame, in words ("seed 7 in A, 8 in B; ..."), or ""
// when both can be parts of one frame. Integrators that --integrator auto chose may differ: each
// task of a frame times its own pilot.
std::string frameDifference(const Part& a, const Part& b) {
    const FrameIdentity &x = *a.frame, &y = *b.frame;
    std::string text;
    const auto differ = [&](const std::string& what, const std::string& inA, const std::string& inB) {
        text += (text.empty() ? "" : "; ") + what + " " + inA + " in " + a.path + ", " + inB + " in " + b.path;
    };
    if (x.scene != y.scene) differ("the scene (with its camera and materials) has the hash", x.scene, y.scene);
    if (x.seed != y.seed) differ("--seed", std::to_string(x.seed), std::to_string(y.seed));
    if (x.integrator != y.integrator && !(chosenByAuto(x.integrator) && chosenByAuto(y.integrator)))
        differ("--integrator", x.integrator, y.integrator);
    if (x.maxDepth != y.maxDepth) differ("--max-depth", std::to_string(x.maxDepth), std::to_string(y.maxDepth));
    if (x.filterWeave != y.filterWeave) differ("--filter", x.filterWeave ? "on" : "off", y.filterWeave ? "on" : "off");
    if (x.sampler != y.sampler) {
        const auto name = [](const std::string& s) { return s.empty() ? std::string("unrecorded (an older woven)") : s; };
        differ("--sampler", name(x.sampler), name(y.sampler));
    }
    return text;
}

// Throws when two parts cannot be parts of one frame; the merged frame's identity, none when a
// part has none (written before parts recorded it: said in one warning).
std::optional<FrameIdentity> commonFrame(const std::vector<Part>& parts) {
    const Part* first = nullptr;
    std::vector<std::string> unrecorded;
    bool mixedPicks = false;
    for (const Part& p : parts) {
        if (!p.frame) {
            unrecorded.push_back(p.path);
            continue;
        }
        if (!first) {
            first = &p;
            continue;
        }
        if (const std::string difference = frameDifference(*first, p); !difference.empty())
            throw std::invalid_argument(first->path + " and " + p.path + " are parts of different frames: " + difference);
        mixedPicks |= p.frame->integrator != first->frame->integrator;
    }
    if (!unrecorded.empty())
        std::cerr << "warning: " << unrecorded.front()
                  << (unrecorded.size() > 1 ? " and " + std::to_string(unrecorded.size() - 1) + " more" : "")
                  << " record no scene, seed or integrator (an older woven wrote them): merged without checking that "
                     "every part is of one frame\n";
    if (!first || !unrecorded.empty()) return std::nullopt;
    FrameIdentity frame = *first->frame;
    if (mixedPicks) {
        std::cerr << "note: --integrator auto chose differently for some parts: the merge is a frame of both integrators, "
                     "not the bits of one render\n";
        frame.integrator = autoIntegrator().name;
    }
    return frame;
}

// The runs of samples that disjoint parts, sorted by their first sample, hold together.
std::vector<SampleRange> heldRuns(const std::vector<Part>& sorted) {
    std::vector<SampleRange> runs;
    for (const Part& p : sorted) {
        if (!runs.empty() && runs.back().end() == p.samples.first) runs.back().count += p.samples.count;
        else runs.push_back(p.samples);
    }
    return runs;
}

// The runs of [0, expected) that none of `held` (sorted, disjoint) covers.
std::vector<SampleRange> gaps(const std::vector<SampleRange>& held, int64_t expected) {
    std::vector<SampleRange> missing;
    int64_t next = 0;
    for (const SampleRange& r : held) {
        if (r.first > next) missing.push_back({next, r.first - next});
        next = r.end();
    }
    if (next < expected) missing.push_back({next, expected - next});
    return missing;
}

// Before any part is read: the output is an EXR that can be written, and no file is named
// twice (its samples would count twice) or as both a part and the output (which would replace it).
void checkFiles(const std::vector<std::string>& inputs, const std::string& out) {
    if (lowerExtension(out) != ".exr")
        throw std::invalid_argument(out + ": merge writes OpenEXR: the output's name must end in .exr");
    checkOutput(out);
    checkOutput(partialName(out));
    for (size_t i = 0; i < inputs.size(); ++i) {
        if (sameFile(inputs[i], out))
            throw std::invalid_argument(inputs[i] + " is both a part and the output: merging would replace it");
        for (size_t j = 0; j < i; ++j)
            if (sameFile(inputs[i], inputs[j]))
                throw std::invalid_argument(inputs[j] + " and " + inputs[i] +
                                            " are the same file: its samples would count twice");
    }
}

void runMerge(const std::vector<std::string>& inputs, const std::string& out, std::optional<int64_t> expected, bool denoise) {
    checkFiles(inputs, out);
    // One part in memory at a time: the sum is added up as they are read, and the ranges are
    // checked once all are known (a merge with overlapping parts writes nothing).
    ExrImage sum;
    std::vector<Part> parts;
    for (const std::string& path : inputs) {
        const ExrImage part = readPart(path);
        if (parts.empty()) {
            sum.image.width = part.image.width;
            sum.image.height = part.image.height;
            sum.sampleCount.assign(part.sampleCount.size(), 0.0f);
            sum.sampleSums.assign(part.sampleSums.size(), ExactSum());
        } else if (part.image.width != sum.image.width || part.image.height != sum.image.height) {
            throw std::invalid_argument(path + ": size differs from " + inputs.front());
        }
        for (size_t i = 0; i < sum.sampleCount.size(); ++i) sum.sampleCount[i] += part.sampleCount[i];
        for (size_t i = 0; i < sum.sampleSums.size(); ++i) sum.sampleSums[i] += part.sampleSums[i];
        if (parts.empty()) sum.passSums.assign(part.passSums.size(), PassSums());
        else if (part.passSums.size() != sum.passSums.size())
            throw std::invalid_argument((part.passSums.empty() ? path : inputs.front()) +
                                        " has no render passes (rendered with --no-passes, or by an older woven) and " +
                                        (part.passSums.empty() ? inputs.front() : path) +
                                        " has: the parts of one frame are rendered alike");
        if (parts.empty()) sum.lacksDirectPass = part.lacksDirectPass;
        else if (!part.passSums.empty() && part.lacksDirectPass != sum.lacksDirectPass)
            throw std::invalid_argument((part.lacksDirectPass ? path : inputs.front()) +
                                        " has no direct-light pass (an older woven wrote it) and " +
                                        (part.lacksDirectPass ? inputs.front() : path) +
                                        " has: parts of one frame come from one version");
        for (size_t i = 0; i < sum.passSums.size(); ++i) sum.passSums[i] += part.passSums[i];
        parts.push_back({path, *part.samples, part.frame});
    }
    if (parts.empty())
        throw std::invalid_argument(out + " not written: no part files" +
                                    (expected ? ", " + describe(SampleRange{0, *expected}) + " missing" : ""));
    std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.samples.first < b.samples.first; });
    checkDisjoint(parts, expected);
    sum.frame = commonFrame(parts);
    const std::vector<SampleRange> held = heldRuns(parts);
    const std::vector<SampleRange> missing = expected ? gaps(held, *expected) : std::vector<SampleRange>();

    sum.image.pixels.resize(sum.sampleCount.size());
    for (size_t i = 0; i < sum.sampleCount.size(); ++i)
        for (int c = 0; c < 3; ++c) sum.image.pixels[i][c] = sum.sampleSums[3 * i + size_t(c)].mean(sum.sampleCount[i]);
    if (held.size() == 1) sum.samples = held.front();
    if (sum.passSums.empty())
        std::cerr << "warning: " << inputs.front()
                  << " has no render passes (rendered with --no-passes, or by an older woven): the merged frame has none\n";

    const std::string partial = partialName(out);
    if (!missing.empty()) {
        writeExr(partial, sum, ExrPrecision::Float);
        throw std::runtime_error(out + " not written: " + describe(missing) + " missing (no part holds them); wrote " +
                                 partial + " from " + describe(held));
    }
    // The merged frame is denoised once, from the merged sums: the beauty the union's render
    // would have, its noisy one kept beside it. The parts' own beauties (denoised or not) are not read.
    if (denoise && !sum.passSums.empty()) {
        sum.noisy = sum.image;
        sum.image = denoiseBeauty(sum.image, sum.passes());
    }
    writeExr(out, sum, ExrPrecision::Float);
    // A partial frame left by an earlier merge that found parts missing is out of date now.
    std::filesystem::remove(partial);
    std::cerr << "wrote " << out << " (" << describe(held) << " from " << parts.size() << " parts)\n";
}

}  // namespace

void addMergeCommand(CLI::App& app) {
    struct Options {
        std::vector<std::string> inputs;
        std::string out;
        std::optional<int64_t> expected;
        bool denoise = true;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "Merge EXR renders of disjoint sample ranges of one frame into the render of their union, exactly");
    cmd->add_option("inputs", o->inputs, "EXR files written by woven render")->check(CLI::ExistingFile);
    cmd->add_option("-o,--out", o->out, "merged EXR")->required();
    cmd->add_option("--expect-samples", o->expected,
                    "the parts must hold samples 0..N-1 of every pixel: when some are missing, OUT is not written, "
                    "the missing samples are named, the parts there are go to OUT.partial.exr and the exit status "
                    "is 1")
        ->transform(wholeNumber(1, kSampleIndexLimit));
    cmd->add_flag("--denoise,!--no-denoise", o->denoise,
                  "denoise the merged frame, as woven render denoises a frame (default: on; the noisy beauty is kept "
                  "as noisy.R/G/B)");
    cmd->callback([o] { runMerge(o->inputs, o->out, o->expected, o->denoise); });
}

}  // namespace woven
