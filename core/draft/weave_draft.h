#pragma once
// A material's weave and thread colours written as a draft, so that a fabric that has no draft
// file (a library preset such as the tartan, a weave typed as (i, j, k)) can be edited thread by
// thread in the draft view and saved as WIF. The draft is the plainest one a weaver would draw:
// a straight threading over one shaft per end of the weave's repeat and a lift plan, one pick a
// row of the repeat; its ends and picks span the weave and the colour sequences together.
#include "draft.h"
#include "woven_params.h"

namespace woven {

// applyDraft(weaveDraft(p), ...) weaves the cloth `p` shows: the same top yarn and colour at
// every thread. Spacing, thickness and yarn types stay the material's (the draft gives none).
// Throws DraftError (prefixed by `name`) when the weave repeats over more ends than a draft has
// shafts, or the repeats of weave and colours together exceed a draft's threads.
Draft weaveDraft(const WovenParams& p, const std::string& name);

}  // namespace woven
