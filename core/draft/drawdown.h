#pragma once
// The interlacement of a draft: at each (end, pick), is the warp on top? Worked out from the
// threading and the shed of each pick, so it takes memory in ends + picks, not ends x picks,
// and one lookup costs the same for any draft size.
#include "draft.h"

namespace woven {

// The shafts that pick `pick` moves: those its treadles are tied to when the draft has a tie-up
// and a treadling, else those its lift plan names.
IndexSet shedOf(const Draft& draft, int pick);

class Drawdown {
public:
    // Throws DraftError, prefixed by `name`, when the draft has no interlacement (no lift plan,
    // and no tie-up with treadling); `draft` must otherwise be valid (validate()).
    Drawdown(const Draft& draft, const std::string& name);

    int ends() const { return int(threading_.size()); }
    int picks() const { return int(sheds_.size()); }

    // Rising shed: the warp is on top where the end is threaded through a shaft that the pick
    // lifts. A sinking shed lowers those shafts instead, so the answer is inverted.
    // 0 <= end < ends(), 0 <= pick < picks().
    bool warpOnTop(int end, int pick) const {
        return (threading_[size_t(end)] & sheds_[size_t(pick)]).any() != sinking_;
    }

private:
    std::vector<IndexSet> threading_;
    std::vector<IndexSet> sheds_;  // per pick: the shafts that move
    bool sinking_;
};

}  // namespace woven
