#include "material_json.h"

#include <filesystem>
#include <stdexcept>

#include "draft_material.h"
#include "wif_reader.h"
#include "woven_params_json.h"

namespace woven {

MaterialJson materialFromJson(const nlohmann::json& j, const WovenParams& base, const std::string& directory,
                              std::vector<std::string>& warnings) {
    if (!j.is_object()) throw std::invalid_argument("a woven material must be a JSON object");
    MaterialJson out;
    out.params = base;
    nlohmann::json rest = j;
    std::optional<Draft> draft;
    if (j.contains("wif")) {
        if (!j["wif"].is_string() || j["wif"].get<std::string>().empty())
            throw std::invalid_argument("'wif' must be the path of a WIF file");
        const std::filesystem::path path(j["wif"].get<std::string>());
        out.wif = path.is_absolute() || directory.empty() ? path.string() : (std::filesystem::path(directory) / path).string();
        draft = readWif(out.wif, warnings);
        DraftWidths widths;
        const bool ownYarns = j.contains("yarns") || j.contains("warp_yarns") || j.contains("weft_yarns");
        widths.weft = !ownYarns && !j.contains("yarn_width");
        widths.warp = !ownYarns && !j.contains("warp_width");
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
        rest.erase("scale");
    }
    out.params = paramsFromJson(rest, out.params);
    return out;
}

}  // namespace woven
