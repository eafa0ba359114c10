#pragma once
// A woven material's JSON object as scene files, `--woven` and the previewer's material files
// hold it: WovenParams' fields (woven_params_json.h) and two keys that need more than the model:
//   "wif": "draft.wif"  a draft file, resolved against a directory (the scene file's, or the
//                       working directory for --woven); the material takes what the draft gives
//                       (applyDraft()) and every other key overrides it, each for its own field
//                       only (weft_color does not carry over to a warp colour the draft gave).
//                       `yarn_width` / `warp_width` keep the draft's thickness off the weft / the
//                       warp; own `yarns`, `warp_yarns` or `weft_yarns` off both.
//   "scale": "draft"    the repeat from the draft's threads per centimetre and the size of the
//                       mesh, which the caller measures (MaterialJson::threadsPerCm).
//   textile keys        "ends_per_cm" / "picks_per_cm" (or per inch) set the repeat as "scale"
//                       does; "warp_count" / "weft_count" set warp_width / yarn_width from the
//                       yarn's diameter (textile_units.h, docs/FABRICS.md).
//   "preset": NAME      a fabric of the library (fabric_library.h) under the other keys.
//   "comment": "..."    a note for people (woven fit says there how it folded the exposure in);
//                       ignored.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "textile_units.h"
#include "woven_params.h"

namespace woven {

struct MaterialJson {
    WovenParams params;
    std::string wif;                         // the draft file read, as resolved; empty when none
    // "scale": "draft" or the thread counts: threads per cm along u and v, which the caller makes
    // `repeat` on its mesh; `scaleKey` names the key that gave them, for messages.
    std::optional<glm::vec2> threadsPerCm;
    std::string scaleKey;
    TextileKeys textile;  // the yarn counts and fibre, for measureFabric()
    std::string preset;   // the fabric file read for "preset"; empty when none
};

// Fields absent from `j` keep their value in `base`. Throws std::invalid_argument naming the key
// for a bad key or value (and the fabric file for a bad preset), DraftError naming the draft file for a draft that cannot be read or
// used. What the draft reader ignored or approximated is added to `warnings`, one line each,
// starting with the draft file's name.
MaterialJson materialFromJson(const nlohmann::json& j, const WovenParams& base, const std::string& directory,
                              std::vector<std::string>& warnings);

}  // namespace woven
