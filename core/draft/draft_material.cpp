#include "draft_material.h"

#include <algorithm>
#include <cmath>

#include "draft_tile.h"

namespace woven {

namespace {

// The width of each thread of a side: thickness / spacing, clamped to the model's range.
std::vector<float> threadWidths(const std::vector<float>& thickness, const std::vector<float>& spacing,
                                const char* side, const std::string& name, std::vector<std::string>& warnings) {
    std::vector<float> widths;
    int thicker = 0;
    for (size_t t = 0; t < thickness.size(); ++t) {
        const float w = thickness[t] / spacing[t];
        thicker += w > 1.0f;
        widths.push_back(std::clamp(w, 1e-3f, 1.0f));
    }
    if (thicker > 0)
        warnings.push_back(name + ": " + std::to_string(thicker) + " " + side +
                           " threads are thicker than their spacing: their yarns fill their cells (width 1)");
    return widths;
}

bool allEqual(const std::vector<float>& v) {
    return std::all_of(v.begin(), v.end(), [&](float x) { return x == v[0]; });
}

}  // namespace

WovenParams applyDraft(const Draft& draft, const std::string& name, const WovenParams& base, DraftWidths use,
                       std::vector<std::string>& warnings) {
    if (draft.ends() > kMaxTileSide || draft.picks() > kMaxTileSide)
        throw DraftError(name + ": the draft's " + std::to_string(draft.ends()) + " ends x " +
                         std::to_string(draft.picks()) + " picks are beyond woven's limit of " +
                         std::to_string(kMaxTileSide) + " threads either way");
    DraftTile tile = draftTile(draft, name);
    WovenParams p = base;
    p.tile = std::move(tile.rows);

    auto colors = [](std::vector<glm::vec3>& list, glm::vec3& single, std::vector<glm::vec3>&& threads) {
        if (threads.empty()) return;
        if (std::all_of(threads.begin(), threads.end(), [&](const glm::vec3& c) { return c == threads[0]; })) {
            single = threads[0];
            list.clear();
        } else {
            list = std::move(threads);
        }
    };
    colors(p.warp_colors, p.warp_color, std::move(tile.warpColors));
    colors(p.weft_colors, p.weft_color, std::move(tile.weftColors));

    // The model reads spacings as proportions of the repeat: divided by their mean they keep their
    // ratios whatever the draft's unit, so a draft in microns is as good as one in inches.
    auto spacing = [](std::vector<float>& list, const std::vector<float>& threads) {
        if (threads.empty()) return;
        if (allEqual(threads)) return list.clear();
        double mean = 0.0;
        for (float s : threads) mean += s;
        mean /= double(threads.size());
        list.clear();
        for (float s : threads) list.push_back(float(s / mean));
    };
    spacing(p.warp_spacing, tile.warpSpacing);
    spacing(p.weft_spacing, tile.weftSpacing);

    // Widths need both thickness and spacing.
    std::vector<float> warpWidths, weftWidths;
    if (use.warp && !tile.warpThickness.empty() && !tile.warpSpacing.empty())
        warpWidths = threadWidths(tile.warpThickness, tile.warpSpacing, "warp", name, warnings);
    if (use.weft && !tile.weftThickness.empty() && !tile.weftSpacing.empty())
        weftWidths = threadWidths(tile.weftThickness, tile.weftSpacing, "weft", name, warnings);
    const bool warpVaries = !warpWidths.empty() && !allEqual(warpWidths);
    const bool weftVaries = !weftWidths.empty() && !allEqual(weftWidths);
    // A side whose threads are alike takes the width as the material's own, with no yarn types.
    if (!warpWidths.empty() && !warpVaries) {
        p.warp_width = warpWidths[0];
        p.warp_yarns.clear();
    }
    if (!weftWidths.empty() && !weftVaries) {
        p.yarn_width = weftWidths[0];
        p.weft_yarns.clear();
    }
    if (!warpVaries && !weftVaries) return p;

    // One yarn type per distinct width; the yarn table is the draft's, so the lists of both
    // sides are replaced (a side whose widths the draft does not give has none).
    auto distinctWidths = [&] {
        std::vector<float> all;
        if (warpVaries) all = warpWidths;
        if (weftVaries) all.insert(all.end(), weftWidths.begin(), weftWidths.end());
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        return all;
    };
    std::vector<float> distinct = distinctWidths();
    if (distinct.size() > size_t(kMaxYarnTypes)) {
        warnings.push_back(name + ": " + std::to_string(distinct.size()) + " different yarn widths, more than woven's " +
                           std::to_string(kMaxYarnTypes) + " yarn types: widths rounded to 1/255");
        // The steps k / 255 (0 as 0.001): 256 at most.
        for (auto* widths : {&warpWidths, &weftWidths})
            for (float& w : *widths) w = std::max(1e-3f, std::round(w * 255.0f) / 255.0f);
        distinct = distinctWidths();
    }
    auto typeOf = [&](float w) { return int(std::lower_bound(distinct.begin(), distinct.end(), w) - distinct.begin()); };
    p.yarns.clear();
    for (float w : distinct) {
        YarnSpec yarn;
        yarn.value[kYarnWidth] = w;
        yarn.set[kYarnWidth] = true;
        p.yarns.push_back(yarn);
    }
    auto assign = [&](std::vector<int>& list, const std::vector<float>& widths, bool varies) {
        list.clear();
        if (varies)
            for (float w : widths) list.push_back(typeOf(w));
    };
    assign(p.warp_yarns, warpWidths, warpVaries);
    assign(p.weft_yarns, weftWidths, weftVaries);
    return p;
}

std::vector<std::string> fieldsSetByDraft(const Draft& draft, DraftWidths widths) {
    std::vector<std::string> fields{"tile"};
    auto side = [&](const DraftThreads& threads, bool useWidths, const char* colors, const char* color,
                    const char* spacing, const char* width, const char* yarns) {
        if (!threads.colors.empty()) fields.emplace_back(colors);  // set, or cleared when one colour is the side's
        const auto& c = threads.colors;
        if (!c.empty() && std::all_of(c.begin(), c.end(), [&](const glm::vec3& x) { return x == c[0]; }))
            fields.emplace_back(color);
        if (!threads.spacing.empty()) fields.emplace_back(spacing);
        if (useWidths && !threads.spacing.empty() && !threads.thickness.empty())
            fields.insert(fields.end(), {width, yarns, "yarns"});
    };
    side(draft.warp, widths.warp, "warp_colors", "warp_color", "warp_spacing", "warp_width", "warp_yarns");
    side(draft.weft, widths.weft, "weft_colors", "weft_color", "weft_spacing", "yarn_width", "weft_yarns");
    std::sort(fields.begin(), fields.end());
    fields.erase(std::unique(fields.begin(), fields.end()), fields.end());
    return fields;
}

glm::vec2 draftThreadsPerCm(const Draft& draft, const std::string& name) {
    auto perCm = [&](const DraftThreads& side, const char* what) {
        if (side.spacing.empty())
            throw DraftError(name + ": the draft gives no " + what + " spacing, so its threads per centimetre are unknown");
        double total = 0.0;
        for (float s : side.spacing) total += toCentimeters(s, side.units);
        return float(side.count / total);
    };
    return {perCm(draft.warp, "warp"), perCm(draft.weft, "weft")};
}

}  // namespace woven
