#include "weave_draft.h"

#include <numeric>

#include "weave_pattern.h"

namespace woven {

namespace {

// Threads of one side: the weave's repeat and the colour sequence's, together.
int threadsSpanning(int weaveRepeat, size_t colours, const char* side, const std::string& name) {
    const long long count = std::lcm(static_cast<long long>(weaveRepeat), static_cast<long long>(std::max<size_t>(colours, 1)));
    if (count > kMaxDraftThreads)
        throw DraftError(name + ": its weave (" + std::to_string(weaveRepeat) + ") and colour sequence (" +
                         std::to_string(colours) + ") repeat together over " + std::to_string(count) + " " + side +
                         ", more than a draft's " + std::to_string(kMaxDraftThreads));
    return int(count);
}

std::vector<glm::vec3> repeated(const std::vector<glm::vec3>& colours, int count) {
    std::vector<glm::vec3> out;
    if (colours.empty()) return out;
    for (int t = 0; t < count; ++t) out.push_back(colours[size_t(t) % colours.size()]);
    return out;
}

}  // namespace

Draft weaveDraft(const WovenParams& p, const std::string& name) {
    const WeavePattern weave = WeavePattern::fromParams(p);
    if (weave.width() > kMaxShafts)
        throw DraftError(name + ": its weave repeats over " + std::to_string(weave.width()) +
                         " ends, more than a draft's " + std::to_string(kMaxShafts) + " shafts");
    Draft draft;
    draft.title = name;
    draft.shafts = weave.width();
    draft.warp.count = threadsSpanning(weave.width(), p.warp_colors.size(), "ends", name);
    draft.weft.count = threadsSpanning(weave.height(), p.weft_colors.size(), "picks", name);
    draft.warp.colors = repeated(p.warp_colors, draft.warp.count);
    draft.weft.colors = repeated(p.weft_colors, draft.weft.count);
    for (int end = 0; end < draft.ends(); ++end) draft.threading.emplace_back().set(size_t(end % weave.width()));
    // Pick V lifts the shafts of the ends whose warp is on top in row V of the repeat.
    for (int pick = 0; pick < draft.picks(); ++pick) {
        IndexSet lifted;
        for (int shaft = 0; shaft < weave.width(); ++shaft)
            if (weave.top(shaft, pick) == YarnType::Warp) lifted.set(size_t(shaft));
        draft.liftplan.push_back(lifted);
    }
    validate(draft, name);
    return draft;
}

}  // namespace woven
