#pragma once
// Undo and redo of the window's material edits (Ctrl+Z, Ctrl+Shift+Z): a stack of whole states
// before each completed edit, one of states undone, and the state shown since the last completed
// edit, the one an edit under way started from. A state is a value (the edits, the draft being
// edited), so an undo restores exactly what the panel showed, whatever control changed it. Free
// of ImGui: the window decides when an edit is complete (a drag released, a field left).
#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

namespace woven {

template <typename State>
class UndoHistory {
public:
    explicit UndoHistory(size_t depth = 200) : depth_(depth) {}

    // A scene opened at `shown`: nothing to undo or redo.
    void reset(State shown) {
        undo_.clear();
        redo_.clear();
        shown_ = std::move(shown);
        pending_ = false;
    }
    // A value changed: an edit is under way (a drag not yet let go is one edit, not one a frame).
    void edited() { pending_ = true; }
    bool pending() const { return pending_; }
    // The edit under way is complete and left `now`: one step back to where it started. What was
    // undone is gone.
    void complete(State now) {
        if (!pending_) return;
        undo_.push_back(std::exchange(shown_, std::move(now)));
        if (undo_.size() > depth_) undo_.pop_front();
        redo_.clear();
        pending_ = false;
    }
    // The state to show instead of `now`, or nothing to undo (complete() an edit under way first).
    std::optional<State> undo(State now) { return step(undo_, redo_, std::move(now)); }
    std::optional<State> redo(State now) { return step(redo_, undo_, std::move(now)); }

    bool canUndo() const { return !undo_.empty() || pending_; }
    bool canRedo() const { return !redo_.empty(); }

private:
    std::optional<State> step(std::deque<State>& from, std::deque<State>& to, State now) {
        if (from.empty()) return std::nullopt;
        shown_ = std::move(from.back());
        from.pop_back();
        to.push_back(std::move(now));
        return shown_;
    }

    size_t depth_;
    std::deque<State> undo_, redo_;
    State shown_{};
    bool pending_ = false;
};

}  // namespace woven
