// `woven pattern`: print the top-yarn map of a weave as MODEL.md draws it, or draw it in thread
// colours as a PNG; the weave is an (i, j, k) pattern, a WIF draft or a woven material (a
// library fabric's "preset" included), whose thread counts also give its cover, weight and repeat.
#include <iostream>
#include <limits>
#include <stdexcept>

#include "commands.h"
#include "number_checks.h"
#include "draft_tile.h"
#include "drawdown_image.h"
#include "fabric_measures.h"
#include "display_transform.h"
#include "image_io.h"
#include "material_json.h"
#include "untrusted_json.h"
#include "weave_pattern.h"
#include "wif_reader.h"

namespace woven {

namespace {

// What a pattern may ask for: a terminal's worth of text many times over (2048 x 2048 cells),
// and a PNG of 64 Mpixels (the drawing takes 12 bytes a pixel while it is made, under 1 GiB).
constexpr int64_t kMaxPrintedCells = int64_t(1) << 22;

// Where neither a draft nor anything else gives colours: a classic drawdown, black where the
// warp is on top.
const glm::vec3 kPlainWarpColor{0.0f}, kPlainWeftColor{1.0f};

struct Weave {
    WeavePattern pattern;
    std::vector<glm::vec3> warpColors{kPlainWarpColor}, weftColors{kPlainWeftColor};
    std::optional<FabricMeasures> measures{};  // a material with thread counts
};

Weave weaveFromDraft(const std::string& path) {
    std::vector<std::string> warnings;
    const Draft draft = readWif(path, warnings);
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    DraftTile tile = draftTile(draft, path);
    Weave weave{WeavePattern::fromRows(tile.rows)};
    if (!tile.warpColors.empty()) weave.warpColors = std::move(tile.warpColors);
    if (!tile.weftColors.empty()) weave.weftColors = std::move(tile.weftColors);
    return weave;
}

// "wif" paths relative to the working directory, as for --woven.
Weave weaveFromMaterial(const std::string& text) {
    std::vector<std::string> warnings;
    MaterialJson read;
    try {
        read = materialFromJson(parseUntrustedJson(text), WovenParams{}, "", warnings);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--material: ") + e.what());
    }
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    const WovenParams& p = read.params;
    Weave weave{WeavePattern::fromParams(p)};
    weave.warpColors = p.warp_colors.empty() ? std::vector<glm::vec3>{p.warp_color} : p.warp_colors;
    weave.weftColors = p.weft_colors.empty() ? std::vector<glm::vec3>{p.weft_color} : p.weft_colors;
    weave.measures = measureMaterial(read);
    return weave;
}

}  // namespace

void addPatternCommand(CLI::App& app) {
    struct Options {
        std::vector<int> pattern{1, 1, 1};
        std::string wif, png, material;
        std::vector<int> size;
        int cellPixels = 8;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("pattern", "Print the top-yarn map of a weave ('-' weft, '|' warp), or draw it as a PNG");
    CLI::Option* pattern = cmd->add_option("--pattern", opts->pattern, "I,J,K: I weft, J warp elements per row, shift K per row")
        ->delimiter(',')->expected(3)->transform(wholeNumber(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    CLI::Option* wif = cmd->add_option("--wif", opts->wif, "a weaving draft (WIF file) instead of --pattern")->excludes(pattern);
    cmd->add_option("--material", opts->material,
                    "a woven material's JSON instead (e.g. '{\"preset\": \"denim\"}'); with thread counts its cover, "
                    "weight and repeat size are printed after the map")
        ->excludes(pattern)->excludes(wif);
    cmd->add_option("--size", opts->size, "W,H: columns and rows (default: one repeat)")
        ->delimiter(',')->expected(2)->transform(wholeNumber(1, std::numeric_limits<int>::max()));
    cmd->add_option("--png", opts->png, "draw the weave in thread colours to this PNG instead of printing it "
                                        "(a draft's colours; black warp, white weft otherwise)");
    cmd->add_option("--cell-pixels", opts->cellPixels, "pixels per weave cell in --png")->transform(wholeNumber(1, 256));
    cmd->callback([opts] {
        Weave weave = [&] {
            if (!opts->wif.empty()) return weaveFromDraft(opts->wif);
            if (!opts->material.empty()) return weaveFromMaterial(opts->material);
            const auto& p = opts->pattern;
            if (p[0] < 0 || p[1] < 0 || p[0] + p[1] < 1 || p[0] + p[1] > 1024)
                throw std::invalid_argument("--pattern: need I, J >= 0 and 1 <= I + J <= 1024");
            return Weave{WeavePattern::regular(p[0], p[1], p[2])};
        }();
        int w = weave.pattern.width(), h = weave.pattern.height();
        if (!opts->size.empty()) {
            w = opts->size[0];
            h = opts->size[1];
            if (w < 1 || h < 1) throw std::invalid_argument("--size: W and H must be at least 1");
        }
        const int64_t cells = int64_t(w) * h;
        if (opts->png.empty() && cells > kMaxPrintedCells)
            throw std::invalid_argument("--size " + std::to_string(w) + "," + std::to_string(h) + ": " +
                                        std::to_string(cells) + " cells, more than the " +
                                        std::to_string(kMaxPrintedCells) + " woven prints (--png draws up to " +
                                        std::to_string(kMaxDrawdownPixels) + " pixels)");
        const int64_t pixels = cells * opts->cellPixels * opts->cellPixels;
        if (!opts->png.empty() && (int64_t(w) * opts->cellPixels > kMaxImageSide ||
                                   int64_t(h) * opts->cellPixels > kMaxImageSide || pixels > int64_t(kMaxDrawdownPixels)))
            throw std::invalid_argument("--size " + std::to_string(w) + "," + std::to_string(h) + " at --cell-pixels " +
                                        std::to_string(opts->cellPixels) + ": --png would draw " +
                                        std::to_string(int64_t(w) * opts->cellPixels) + " x " +
                                        std::to_string(int64_t(h) * opts->cellPixels) + " pixels, more than woven draws (" +
                                        std::to_string(kMaxImageSide) + " on a side, " +
                                        std::to_string(kMaxDrawdownPixels) + " pixels)");
        if (opts->png.empty()) {
            std::cout << weave.pattern.draw(w, h);
            if (weave.measures) std::cout << describe(*weave.measures) << "\n";
            return;
        }
        if (weave.measures) std::cout << describe(*weave.measures) << "\n";
        // Clamp: the PNG holds the thread colours exactly, with no tone curve.
        writePng(opts->png, drawdownImage(weave.pattern, weave.warpColors, weave.weftColors, w, h, opts->cellPixels),
                 DisplayTransform{0.0f, ToneMap::Clamp});
    });
}

}  // namespace woven
