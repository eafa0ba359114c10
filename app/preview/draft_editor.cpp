#include "draft_editor.h"

#include <stdexcept>

#include "draft_material.h"
#include "drawdown.h"
#include "wif_reader.h"
#include "wif_writer.h"

namespace woven {

namespace {

void flip(IndexSet& set, int index) { set.flip(size_t(index)); }

template <class T>
void repeatTo(std::vector<T>& list, int count) {
    if (list.empty()) return;
    const size_t old = list.size();
    list.resize(size_t(count), list[0]);
    for (size_t i = old; i < list.size(); ++i) list[i] = list[i % old];
}

}  // namespace

DraftEditor::DraftEditor(Draft draft, std::string name) : draft_(std::move(draft)), name_(std::move(name)) {
    validate(draft_, name_);
    requireInterlacement(draft_, name_);
}

DraftEditor DraftEditor::open(const std::string& path, std::vector<std::string>& warnings) {
    return DraftEditor(readWif(path, warnings), path);
}

// A lift plan kept beside tie-up and treadling (for writing back) follows them.
void DraftEditor::keepLiftplanInStep() {
    if (draft_.usesTieup() && !draft_.liftplan.empty())
        for (int pick = 0; pick < draft_.picks(); ++pick) draft_.liftplan[size_t(pick)] = shedOf(draft_, pick);
}

void DraftEditor::toggleThreading(int end, int shaft) {
    flip(draft_.threading.at(size_t(end)), shaft);
}

void DraftEditor::toggleTieup(int treadle, int shaft) {
    flip(draft_.tieup.at(size_t(treadle)), shaft);
    keepLiftplanInStep();
}

void DraftEditor::toggleTreadling(int pick, int treadle) {
    flip(draft_.treadling.at(size_t(pick)), treadle);
    keepLiftplanInStep();
}

void DraftEditor::toggleLiftplan(int pick, int shaft) {
    if (draft_.usesTieup()) throw std::logic_error("the draft is driven by its tie-up and treadling");
    flip(draft_.liftplan.at(size_t(pick)), shaft);
}

bool DraftEditor::warpOnTop(int end, int pick) const { return Drawdown(draft_, name_).warpOnTop(end, pick); }

glm::vec3 DraftEditor::color(DraftSide side, int thread, const glm::vec3& unset) const {
    const DraftThreads& t = threads(side);
    return t.colors.empty() ? unset : t.colors.at(size_t(thread));
}

void DraftEditor::setColor(DraftSide side, int thread, const glm::vec3& color, const glm::vec3& unset) {
    DraftThreads& t = threads(side);
    if (t.colors.empty()) t.colors.assign(size_t(t.count), unset);
    t.colors.at(size_t(thread)) = glm::clamp(color, 0.0f, 1.0f);
}

std::pair<int, int> DraftEditor::stripe(DraftSide side, int thread) const {
    const DraftThreads& t = threads(side);
    if (t.colors.empty()) return {0, t.count - 1};
    int first = thread, last = thread;
    while (first > 0 && t.colors[size_t(first) - 1] == t.colors[size_t(thread)]) --first;
    while (last + 1 < t.count && t.colors[size_t(last) + 1] == t.colors[size_t(thread)]) ++last;
    return {first, last};
}

void DraftEditor::setStripeColor(DraftSide side, int thread, const glm::vec3& color, const glm::vec3& unset) {
    const auto [first, last] = stripe(side, thread);
    DraftThreads& t = threads(side);
    if (t.colors.empty()) t.colors.assign(size_t(t.count), unset);
    for (int k = first; k <= last; ++k) t.colors[size_t(k)] = glm::clamp(color, 0.0f, 1.0f);
}

void DraftEditor::setThreadCount(DraftSide side, int count) {
    if (count < 1 || count > kMaxDraftThreads)
        throw std::invalid_argument("a draft has 1 to " + std::to_string(kMaxDraftThreads) + " threads a side");
    DraftThreads& t = threads(side);
    repeatTo(t.colors, count);
    repeatTo(t.spacing, count);
    repeatTo(t.thickness, count);
    if (side == DraftSide::Warp) {
        repeatTo(draft_.threading, count);
    } else {
        repeatTo(draft_.treadling, count);
        repeatTo(draft_.liftplan, count);
    }
    t.count = count;
}

WovenParams DraftEditor::material(const WovenParams& base) const {
    std::vector<std::string> warnings;  // the reader's were shown when the draft was opened
    return applyDraft(draft_, name_, base, DraftWidths{}, warnings);
}

void DraftEditor::save(const std::string& path) {
    writeWif(path, draft_);
    name_ = path;
}

}  // namespace woven
