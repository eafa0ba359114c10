#include "material_json.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <tuple>

#include "draft_material.h"
#include "fabric_library.h"
#include "wif_reader.h"
#include "woven_params_json.h"

namespace woven {

namespace {

// The yarn widths the counts give: diameter / spacing, at most 1 (a jammed side fills its cells,
// with a warning).
void setWidthsFromCounts(const TextileKeys& t, const glm::vec2& threadsPerCm, nlohmann::json& rest,
                         std::vector<std::string>& warnings) {
    const char* threads[2] = {"ends", "picks"};
    const std::optional<double> tex[2] = {t.warpTex, t.weftTex};
    const char* count[2] = {"warp_count", "weft_count"};
    const char* width[2] = {"warp_width", "yarn_width"};
    for (int side = 0; side < 2; ++side) {
        if (!tex[side]) continue;
        const double fraction = yarnDiameterCm(*tex[side], t.fibreDensity) * threadsPerCm[side];
        if (fraction > 1.0) {
            char line[200];
            std::snprintf(line, sizeof line, "'%s' at %.4g %s per cm: yarns %.2f times their spacing, jammed (%s 1)",
                          count[side], threadsPerCm[side], threads[side], fraction, width[side]);
            warnings.push_back(line);
        }
        rest[width[side]] = std::max(std::min(fraction, 1.0), 1e-3);
    }
}

}  // namespace

namespace {

// A key given in the material's own JSON replaces what a lower layer (its draft, its preset, the
// scene's "*" entry, the base) gave for the same thing in another field: `pattern` the tile (a
// draft's weave: its threads keep their colours, yarns and spacing by position), `weft_color` and
// `warp_color` the side's per-thread colours (every pick, or every end, that colour).
void replaceByGivenKeys(const nlohmann::json& given, nlohmann::json& rest, WovenParams& lower) {
    static const struct {
        const char* key;
        const char* replaced;
        void (*clear)(WovenParams&);
    } rules[] = {{"pattern", "tile", [](WovenParams& p) { p.tile.clear(); }},
                 {"weft_color", "weft_colors", [](WovenParams& p) { p.weft_colors.clear(); }},
                 {"warp_color", "warp_colors", [](WovenParams& p) { p.warp_colors.clear(); }}};
    for (const auto& rule : rules)
        if (given.contains(rule.key) && !given.contains(rule.replaced)) {
            rest.erase(rule.replaced);
            rule.clear(lower);
        }
}

}  // namespace

MaterialJson materialFromJson(const nlohmann::json& given, const WovenParams& base, const std::string& directory,
                              std::vector<std::string>& warnings) {
    if (!given.is_object()) throw std::invalid_argument("a woven material must be a JSON object");
    MaterialJson out;
    nlohmann::json j = given;
    if (given.contains("preset")) {
        Fabric fabric;
        j = withPreset(given, fabric);
        // The fabric alone first, so that a mistake in its file names the file.
        MaterialJson alone;
        try {
            std::vector<std::string> ignored;
            alone = materialFromJson(fabric.material, base, "", ignored);
        } catch (const std::exception& e) {
            throw std::invalid_argument(fabric.file + ": " + e.what());
        }
        // A repeat in place of the fabric's thread counts keeps the widths its counts gave.
        if (!readTextileKeys(j).threadsPerCm && !j.contains("scale"))
            for (const auto& [count, width, value] : {std::tuple{"warp_count", "warp_width", alone.params.warp_width},
                                                      std::tuple{"weft_count", "yarn_width", alone.params.yarn_width}})
                if (j.contains(count) && !given.contains(count)) j.erase(count), j[width] = value;
        out.preset = fabric.file;
    }
    out.params = base;
    out.textile = readTextileKeys(j);
    nlohmann::json rest = j;
    for (const char* key : textileKeyNames()) rest.erase(key);
    if (j.contains("comment")) {
        // A note for people (woven fit writes how the exposure was folded in); the material ignores it.
        if (!j["comment"].is_string()) throw std::invalid_argument("'comment' must be a string");
        rest.erase("comment");
    }
    std::optional<Draft> draft;
    if (j.contains("wif")) {
        if (!j["wif"].is_string() || j["wif"].get<std::string>().empty())
            throw std::invalid_argument("'wif' must be the path of a WIF file");
        const std::filesystem::path path(j["wif"].get<std::string>());
        out.wif = path.is_absolute() || directory.empty() ? path.string() : (std::filesystem::path(directory) / path).string();
        draft = readWif(out.wif, warnings);
        DraftWidths widths;
        const bool ownYarns = j.contains("yarns") || j.contains("warp_yarns") || j.contains("weft_yarns");
        widths.weft = !ownYarns && !j.contains("yarn_width") && !out.textile.weftTex;
        widths.warp = !ownYarns && !j.contains("warp_width") && !out.textile.warpTex;
        out.params = applyDraft(*draft, out.wif, base, widths, warnings);
        rest.erase("wif");
        // What the draft set stays unless its own key is given: a fallback (warp_color <-
        // weft_color, warp_width <- yarn_width) must not carry a weft key over the draft's warp.
        const nlohmann::json drafted = paramsToJson(out.params);
        for (const std::string& field : fieldsSetByDraft(*draft, widths))
            if (!j.contains(field) && drafted.contains(field)) rest[field] = drafted[field];
    }
    if (j.contains("scale")) {
        if (j["scale"] != "draft") throw std::invalid_argument("'scale' must be \"draft\" (the draft's threads per cm on the mesh)");
        if (!draft) throw std::invalid_argument("'scale': \"draft\" needs a draft: give \"wif\"");
        if (j.contains("repeat")) throw std::invalid_argument("'scale': \"draft\" and 'repeat' both set the repeat: give one");
        out.threadsPerCm = draftThreadsPerCm(*draft, out.wif);
        out.scaleKey = "'scale': \"draft\"";
        rest.erase("scale");
    } else if (out.textile.threadsPerCm) {
        out.threadsPerCm = glm::vec2(*out.textile.threadsPerCm);
        out.scaleKey = j.contains("ends_per_cm") ? "'ends_per_cm'" : "'ends_per_inch'";
    }
    if (out.textile.warpTex || out.textile.weftTex) {
        if (!out.threadsPerCm)
            throw std::invalid_argument(std::string(out.textile.warpTex ? "'warp_count'" : "'weft_count'") +
                                        " needs the thread spacing: give 'ends_per_cm' and 'picks_per_cm' (or per "
                                        "inch), or a draft with \"scale\": \"draft\"");
        setWidthsFromCounts(out.textile, *out.threadsPerCm, rest, warnings);
    }
    replaceByGivenKeys(given, rest, out.params);
    out.params = paramsFromJson(rest, out.params);
    return out;
}

}  // namespace woven
