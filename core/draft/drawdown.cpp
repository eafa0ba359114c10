#include "drawdown.h"

namespace woven {

IndexSet shedOf(const Draft& draft, int pick) {
    if (!draft.usesTieup()) return draft.liftplan[size_t(pick)];
    IndexSet shed;
    for (int treadle = 0; treadle < draft.treadles; ++treadle)
        if (draft.treadling[size_t(pick)][size_t(treadle)]) shed |= draft.tieup[size_t(treadle)];
    return shed;
}

Drawdown::Drawdown(const Draft& draft, const std::string& name)
    : threading_(draft.threading), sinking_(!draft.risingShed) {
    requireInterlacement(draft, name);
    sheds_.reserve(size_t(draft.picks()));
    for (int pick = 0; pick < draft.picks(); ++pick) sheds_.push_back(shedOf(draft, pick));
}

}  // namespace woven
