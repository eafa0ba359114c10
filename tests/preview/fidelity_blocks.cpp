#include "fidelity_blocks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "display_transform.h"
#include "fabric_library.h"

namespace woven::test {
namespace {

constexpr int kBlock = 8;

// Calls f(x0, y0) for each block wholly in the mask.
template <class F>
void forEachBlock(int width, int height, const std::vector<uint8_t>& mask, F f) {
    for (int by = 0; by + kBlock <= height; by += kBlock)
        for (int bx = 0; bx + kBlock <= width; bx += kBlock) {
            bool whole = true;
            for (int y = by; y < by + kBlock; ++y)
                for (int x = bx; x < bx + kBlock; ++x) whole = whole && mask[size_t(y) * size_t(width) + size_t(x)];
            if (whole) f(bx, by);
        }
}

glm::dvec3 blockSum(const Image& image, int bx, int by) {
    glm::dvec3 sum(0.0);
    for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) sum += glm::dvec3(image.at(x, y));
    return sum;
}

double l1(const glm::dvec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// The median and worst of each block's `difference` over (|core|_1 + floor).
BlockErrors summarise(const std::vector<std::pair<double, double>>& differenceAndCore) {
    BlockErrors e;
    e.blocks = differenceAndCore.size();
    if (differenceAndCore.empty()) return e;
    double coreTotal = 0.0;
    for (const auto& [difference, reference] : differenceAndCore) coreTotal += reference;
    const double floor = 0.02 * coreTotal / double(differenceAndCore.size());
    std::vector<double> errors;
    for (const auto& [difference, reference] : differenceAndCore) errors.push_back(difference / (reference + floor));
    std::sort(errors.begin(), errors.end());
    e.median = errors[errors.size() / 2];
    e.worst = errors.back();
    return e;
}

}  // namespace

std::vector<FidelitySubject> fidelitySubjects() {
    std::vector<FidelitySubject> all;
    for (const std::string& name : fabricNames()) all.push_back({name, {{"preset", name}}});
    std::vector<std::string> drafts;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(WOVEN_ASSETS_DIR) + "/drafts"))
        if (entry.path().extension() == ".wif") drafts.push_back(entry.path().string());
    std::sort(drafts.begin(), drafts.end());
    for (const std::string& wif : drafts)
        all.push_back({"draft_" + std::filesystem::path(wif).stem().string(), {{"wif", wif}}});
    return all;
}

std::string testName(std::string name) {
    std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
    return name;
}

BlockErrors blockErrors(const Image& preview, const Image& core, const std::vector<uint8_t>& mask) {
    std::vector<std::pair<double, double>> sums;
    forEachBlock(core.width, core.height, mask, [&](int bx, int by) {
        const glm::dvec3 c = blockSum(core, bx, by);
        sums.emplace_back(l1(blockSum(preview, bx, by) - c), l1(c));
    });
    return summarise(sums);
}

BlockErrors blockNoise(const Image& core, const Image& variance, const std::vector<uint8_t>& mask) {
    std::vector<std::pair<double, double>> sums;
    forEachBlock(core.width, core.height, mask, [&](int bx, int by) {
        // Of the block's sum of pixel means: the standard deviation sqrt(sum of variances) a channel.
        const glm::dvec3 sd = glm::sqrt(blockSum(variance, bx, by));
        sums.emplace_back(std::sqrt(2.0 / 3.14159265358979323846) * l1(sd), l1(blockSum(core, bx, by)));
    });
    return summarise(sums);
}

void writeFidelityPicture(const std::string& name, const Image& preview, const Image& core, int shrink) {
    const char* folder = std::getenv("WOVEN_FIDELITY_PICTURES");
    if (!folder) return;
    Image picture;
    const int side = core.width / shrink;
    picture.width = 2 * side;
    picture.height = core.height / shrink;
    picture.pixels.assign(size_t(picture.width) * size_t(picture.height), glm::vec3(0.0f));
    const Image* halves[2] = {&preview, &core};
    for (int half = 0; half < 2; ++half)
        for (int y = 0; y < picture.height; ++y)
            for (int x = 0; x < side; ++x) {
                glm::vec3 sum(0.0f);
                for (int dy = 0; dy < shrink; ++dy)
                    for (int dx = 0; dx < shrink; ++dx) sum += halves[half]->at(shrink * x + dx, shrink * y + dy);
                picture.at(half * side + x, y) = sum / float(shrink * shrink);
            }
    writePng(std::string(folder) + "/" + name + ".png", picture);
}

}  // namespace woven::test
