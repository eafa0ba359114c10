#pragma once
// What a draft makes of a woven material (MODEL.md section 6, docs/DRAFTS.md): the weave tile,
// each thread's colour and spacing, and its yarn's width from thickness / spacing. Weft pick V
// is row V (along u), warp end U column U (along v), as draftTile() lays them out.
#include <string>
#include <vector>

#include "draft.h"
#include "woven_params.h"

namespace woven {

// Which sides' yarn widths the material takes from the draft; a side whose width the material
// sets itself keeps its own.
struct DraftWidths {
    bool warp = true, weft = true;
};

// `base` with what `draft` gives, the rest kept:
// - `tile`, from the drawdown;
// - per side, colours as warp_colors / weft_colors, or warp_color / weft_color when every thread
//   of the side has the same;
// - spacing as warp_spacing / weft_spacing, none when even;
// - widths (thickness / spacing, clamped to [0.001, 1]: a thread thicker than its spacing fills
//   its cell, with a warning), for the sides in `widths`: warp_width / yarn_width when a side's
//   threads are alike, else yarn types of one width each (`yarns`, `warp_yarns`, `weft_yarns`;
//   beyond kMaxYarnTypes distinct widths they are rounded to 1/255, with a warning; a side
//   whose widths the draft does not give then has no yarn types).
// Throws DraftError (prefixed by `name`) for a draft without interlacement or beyond the model's
// tile limits; `draft` must otherwise be valid (validate()).
WovenParams applyDraft(const Draft& draft, const std::string& name, const WovenParams& base, DraftWidths widths,
                       std::vector<std::string>& warnings);

// The names of the fields applyDraft() gives values for `draft` with `widths`, whatever the
// base: what a material saved beside its draft leaves out, so that the draft sets them again
// when it is read back (materialFromJson()).
std::vector<std::string> fieldsSetByDraft(const Draft& draft, DraftWidths widths = {});

// The draft's threads per centimetre: warp ends across u, weft picks across v, from their
// spacing. Throws DraftError (prefixed by `name`) when a side gives no spacing.
glm::vec2 draftThreadsPerCm(const Draft& draft, const std::string& name);

}  // namespace woven
