#pragma once
// The draft the window edits (docs/DRAFTS.md): a Draft with the edits its view offers, each
// keeping the draft valid, and what the draft makes of the material being tuned. No ImGui here:
// the view (draft_view.h) turns clicks into these calls, and tests call them directly.
#include <string>
#include <vector>

#include "draft.h"
#include "woven_params.h"

namespace woven {

enum class DraftSide { Warp, Weft };

class DraftEditor {
public:
    // Throws DraftError (naming `name`) for a draft that is not valid or has no interlacement.
    DraftEditor(Draft draft, std::string name);
    // Reads a WIF file; what the reader ignored or approximated goes to `warnings`.
    static DraftEditor open(const std::string& path, std::vector<std::string>& warnings);

    const Draft& draft() const { return draft_; }
    const std::string& name() const { return name_; }  // the file it came from or was saved to

    // Cell toggles, numbered from 0. The draft's lift plan follows an edited tie-up or treadling
    // (when it has one beside them), so the file written stays consistent.
    void toggleThreading(int end, int shaft);
    void toggleTieup(int treadle, int shaft);
    void toggleTreadling(int pick, int treadle);
    void toggleLiftplan(int pick, int shaft);  // a draft driven by its lift plan only
    // Whether the warp is on top at (end, pick) on the face the material shows (a Drawdown
    // made for this one question: a view that draws many cells makes its own).
    bool warpOnTop(int end, int pick) const;

    // Colours, linear RGB. A draft without colours for that side starts from `unset` for every
    // thread (the material's colour for it, so that nothing else changes).
    glm::vec3 color(DraftSide side, int thread, const glm::vec3& unset) const;
    void setColor(DraftSide side, int thread, const glm::vec3& color, const glm::vec3& unset);
    // The stripe of a thread: the run of neighbouring threads with its colour, [first, last].
    std::pair<int, int> stripe(DraftSide side, int thread) const;
    void setStripeColor(DraftSide side, int thread, const glm::vec3& color, const glm::vec3& unset);

    // More or fewer threads: new ones repeat the draft from its start (threading, treadling or
    // lift plan, colour, spacing, thickness), so a repeat is extended as a weaver would.
    void setThreadCount(DraftSide side, int count);

    // `base` with what the draft gives (applyDraft(), every width the draft has).
    WovenParams material(const WovenParams& base) const;

    // Writes the draft as a WIF file (atomically) and remembers `path` as its name.
    void save(const std::string& path);

private:
    DraftThreads& threads(DraftSide side) { return side == DraftSide::Warp ? draft_.warp : draft_.weft; }
    const DraftThreads& threads(DraftSide side) const { return side == DraftSide::Warp ? draft_.warp : draft_.weft; }
    void keepLiftplanInStep();

    Draft draft_;
    std::string name_;
};

}  // namespace woven
