#include "drawdown.h"

namespace woven {

Drawdown::Drawdown(const Draft& draft, const std::string& name)
    : threading_(draft.threading), sinking_(!draft.risingShed) {
    requireInterlacement(draft, name);
    if (!draft.usesTieup()) {
        sheds_ = draft.liftplan;
        return;
    }
    sheds_.resize(draft.treadling.size());
    for (size_t pick = 0; pick < sheds_.size(); ++pick)
        for (int treadle = 0; treadle < draft.treadles; ++treadle)
            if (draft.treadling[pick][size_t(treadle)]) sheds_[pick] |= draft.tieup[size_t(treadle)];
}

}  // namespace woven
