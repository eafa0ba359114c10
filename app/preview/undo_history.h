#pragma once
// Undo and redo of the window's material edits (Ctrl+Z, Ctrl+Shift+Z): a stack of whole states
// before each committed edit and one of states undone. A state is a value (the edits, the draft
// being edited), so an undo restores exactly what the panel showed, whatever control changed it.
// Free of ImGui: the window decides when an edit is complete (a drag released, a field left).
#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

namespace woven {

template <typename State>
class UndoHistory {
public:
    explicit UndoHistory(size_t depth = 200) : depth_(depth) {}

    // An edit was completed; `before` is the state it started from. What was undone is gone.
    void commit(State before) {
        undo_.push_back(std::move(before));
        if (undo_.size() > depth_) undo_.pop_front();
        redo_.clear();
    }
    // The state to show instead of `current`, or nothing to undo.
    std::optional<State> undo(State current) { return step(undo_, redo_, std::move(current)); }
    std::optional<State> redo(State current) { return step(redo_, undo_, std::move(current)); }

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    void clear() {
        undo_.clear();
        redo_.clear();
    }

private:
    static std::optional<State> step(std::deque<State>& from, std::deque<State>& to, State current) {
        if (from.empty()) return std::nullopt;
        State state = std::move(from.back());
        from.pop_back();
        to.push_back(std::move(current));
        return state;
    }

    size_t depth_;
    std::deque<State> undo_, redo_;
};

}  // namespace woven
