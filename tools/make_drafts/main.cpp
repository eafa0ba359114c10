// make_drafts: builds the project's sample drafts in code and writes them as WIF files with
// woven's writer (assets/drafts, docs/DRAFTS.md). Deterministic: the same build writes the
// same bytes. From the repository root: build/tools/make_drafts/make_drafts assets/drafts
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "srgb.h"
#include "wif_writer.h"

namespace {

using woven::Draft;
using woven::DraftThreads;
using woven::IndexSet;

glm::vec3 srgb8(int r, int g, int b) {
    return {woven::srgbToLinear(r / 255.0f), woven::srgbToLinear(g / 255.0f), woven::srgbToLinear(b / 255.0f)};
}

IndexSet only(int index) {
    IndexSet set;
    set.set(size_t(index));
    return set;
}

// End e on shaft e mod shafts: the straight draw.
std::vector<IndexSet> straightDraw(int ends, int shafts) {
    std::vector<IndexSet> threading;
    for (int e = 0; e < ends; ++e) threading.push_back(only(e % shafts));
    return threading;
}

// Treadle t lifts shafts t .. t + up - 1 (mod shafts): an up/down twill when treadled in order.
std::vector<IndexSet> twillTieup(int shafts, int up) {
    std::vector<IndexSet> tieup(static_cast<size_t>(shafts));
    for (int t = 0; t < shafts; ++t)
        for (int k = 0; k < up; ++k) tieup[size_t(t)].set(size_t((t + k) % shafts));
    return tieup;
}

// Colour stripes: {count, colour} runs, one entry per thread.
std::vector<glm::vec3> stripes(const std::vector<std::pair<int, glm::vec3>>& runs) {
    std::vector<glm::vec3> colors;
    for (const auto& [count, color] : runs) colors.insert(colors.end(), size_t(count), color);
    return colors;
}

DraftThreads threads(std::vector<glm::vec3> colors, float spacing, float thickness, woven::LengthUnit units) {
    DraftThreads t;
    t.count = int(colors.size());
    t.spacing.assign(colors.size(), spacing);
    t.thickness.assign(colors.size(), thickness);
    t.colors = std::move(colors);
    t.units = units;
    return t;
}

std::vector<glm::vec3> distinct(const Draft& draft) {
    std::vector<glm::vec3> palette;
    for (const DraftThreads* side : {&draft.warp, &draft.weft})
        for (const glm::vec3& c : side->colors)
            if (std::find(palette.begin(), palette.end(), c) == palette.end()) palette.push_back(c);
    return palette;
}

// 2/2 twill on 4 shafts with 4 dark and 4 light threads in warp and weft.
Draft houndstooth() {
    const glm::vec3 dark = srgb8(32, 30, 36), light = srgb8(236, 228, 210);
    Draft d;
    d.title = "Houndstooth: 2/2 twill, 4 dark 4 light in warp and weft";
    d.shafts = d.treadles = 4;
    d.warp = threads(stripes({{4, dark}, {4, light}}), 0.05f, 0.045f, woven::LengthUnit::Centimeters);
    d.weft = d.warp;
    d.threading = straightDraw(8, 4);
    d.tieup = twillTieup(4, 2);
    for (int p = 0; p < 8; ++p) d.treadling.push_back(only(p % 4));
    d.palette = distinct(d);
    return d;
}

// Plain weave in white and red stripes of 8 threads both ways, driven by a lift plan (a table
// loom's draft: no treadles).
Draft gingham() {
    const glm::vec3 white = srgb8(245, 244, 238), red = srgb8(188, 32, 46);
    Draft d;
    d.title = "Gingham: plain weave, 8 white 8 red in warp and weft (lift plan)";
    d.shafts = 2;
    d.warp = threads(stripes({{8, white}, {8, red}}), 0.04f, 0.036f, woven::LengthUnit::Centimeters);
    d.weft = d.warp;
    d.threading = straightDraw(16, 2);
    for (int p = 0; p < 16; ++p) d.liftplan.push_back(only(p % 2));
    d.palette = distinct(d);
    return d;
}

// 2/2 twill, navy warp with thicker, wider-spaced cream and red stripes, slate weft; 50 navy
// ends per inch.
Draft twillStripes() {
    const glm::vec3 navy = srgb8(28, 38, 78), cream = srgb8(232, 222, 196), red = srgb8(170, 30, 40),
                    slate = srgb8(104, 116, 142);
    Draft d;
    d.title = "2/2 twill with stripes: navy warp with thick cream and red stripes, slate weft";
    d.shafts = d.treadles = 4;
    d.warp = threads(stripes({{12, navy}, {4, cream}, {12, navy}, {4, red}}), 0.02f, 0.018f, woven::LengthUnit::Inches);
    // The stripe yarns are thicker and take more room: the reed spreads them wider.
    for (int e = 0; e < d.warp.count; ++e)
        if (d.warp.colors[size_t(e)] != navy) {
            d.warp.thickness[size_t(e)] = 0.024f;
            d.warp.spacing[size_t(e)] = 0.026f;
        }
    d.weft = threads(stripes({{4, slate}}), 0.02f, 0.018f, woven::LengthUnit::Inches);
    d.threading = straightDraw(d.warp.count, 4);
    d.tieup = twillTieup(4, 2);
    for (int p = 0; p < 4; ++p) d.treadling.push_back(only(p));
    d.palette = distinct(d);
    return d;
}

// Denim: 3/1 right-hand twill, warp-faced, indigo warp and undyed weft, at the thread counts of
// a classic 14 oz jeans denim (about 64 ends and 40 picks per inch, 25 and 16 per cm: Paul (ed.),
// Denim: Manufacture, Finishing and Applications, 2015, ch. 1); the yarns nearly fill their
// spacing, as in a dense warp-faced cloth.
Draft denim() {
    const glm::vec3 indigo = srgb8(38, 52, 96), ecru = srgb8(226, 220, 200);
    Draft d;
    d.title = "Denim: 3/1 twill, indigo warp, ecru weft, 25 ends and 16 picks per cm";
    d.shafts = d.treadles = 4;
    d.warp = threads(stripes({{4, indigo}}), 0.04f, 0.038f, woven::LengthUnit::Centimeters);
    d.weft = threads(stripes({{4, ecru}}), 0.0625f, 0.055f, woven::LengthUnit::Centimeters);
    d.threading = straightDraw(4, 4);
    d.tieup = twillTieup(4, 3);
    for (int p = 0; p < 4; ++p) d.treadling.push_back(only(p));
    d.palette = distinct(d);
    return d;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Writes woven's sample drafts (houndstooth, gingham, twill with stripes, denim) as WIF files"};
    std::string dir;
    app.add_option("dir", dir, "output folder (it must exist)")->required()->check(CLI::ExistingDirectory);
    CLI11_PARSE(app, argc, argv);
    try {
        for (const auto& [name, draft] : {std::pair<const char*, Draft>{"houndstooth.wif", houndstooth()},
                                          {"gingham.wif", gingham()}, {"twill_stripes.wif", twillStripes()},
                                          {"denim.wif", denim()}}) {
            const std::string path = (std::filesystem::path(dir) / name).string();
            woven::writeWif(path, draft);
            std::cerr << "wrote " << path << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "make_drafts: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
