// `woven merge`: combine EXR renders of disjoint sample ranges of one frame (for example the
// tasks of a Slurm job array) into the render of their union, weighting each pixel's mean by
// its sample count N.
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "image_io.h"

namespace woven {

namespace {

void runMerge(const std::vector<std::string>& inputs, const std::string& out) {
    ExrImage sum;
    for (const std::string& path : inputs) {
        const ExrImage part = readExr(path);
        if (part.sampleCount.empty())
            throw std::invalid_argument(path + ": has no sample-count channel N (render with -o FILE.exr)");
        if (sum.sampleCount.empty()) {
            sum.image.width = part.image.width;
            sum.image.height = part.image.height;
            sum.image.pixels.assign(part.image.pixels.size(), glm::vec3(0.0f));
            sum.sampleCount.assign(part.sampleCount.size(), 0.0f);
        } else if (part.image.width != sum.image.width || part.image.height != sum.image.height) {
            throw std::invalid_argument(path + ": size differs from " + inputs.front());
        }
        for (size_t i = 0; i < sum.sampleCount.size(); ++i) {
            sum.image.pixels[i] += part.image.pixels[i] * part.sampleCount[i];
            sum.sampleCount[i] += part.sampleCount[i];
        }
    }
    for (size_t i = 0; i < sum.sampleCount.size(); ++i)
        if (sum.sampleCount[i] > 0.0f) sum.image.pixels[i] /= sum.sampleCount[i];
    writeExr(out, sum, ExrPrecision::Float);
    std::cerr << "wrote " << out << " (" << inputs.size() << " parts)\n";
}

}  // namespace

void addMergeCommand(CLI::App& app) {
    struct Options {
        std::vector<std::string> inputs;
        std::string out;
    };
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("merge", "Merge EXR renders of disjoint sample ranges, weighted by sample count");
    cmd->add_option("inputs", o->inputs, "EXR files written by woven render")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--out", o->out, "merged EXR")->required();
    cmd->callback([o] { runMerge(o->inputs, o->out); });
}

}  // namespace woven
