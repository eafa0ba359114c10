// The window's undo history: each completed edit is one step back, a new edit drops what was
// undone, and the depth is bounded.
#include <gtest/gtest.h>

#include <string>

#include "undo_history.h"

namespace woven::test {
namespace {

TEST(UndoHistory, StepsBackAndForwardThroughCompletedEdits) {
    UndoHistory<std::string> history;
    EXPECT_FALSE(history.undo("a"));
    history.commit("a");  // a -> b
    history.commit("b");  // b -> c
    EXPECT_EQ(*history.undo("c"), "b");
    EXPECT_EQ(*history.undo("b"), "a");
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(*history.redo("a"), "b");
    EXPECT_EQ(*history.redo("b"), "c");
    EXPECT_FALSE(history.redo("c"));
}

TEST(UndoHistory, ANewEditDropsWhatWasUndone) {
    UndoHistory<int> history;
    history.commit(1);
    EXPECT_EQ(*history.undo(2), 1);
    history.commit(1);  // 1 -> 3
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(*history.undo(3), 1);
}

TEST(UndoHistory, KeepsItsDepth) {
    UndoHistory<int> history(3);
    for (int i = 0; i < 10; ++i) history.commit(i);
    int undone = 0;
    for (int state = 10; std::optional<int> before = history.undo(state); state = *before) ++undone;
    EXPECT_EQ(undone, 3);
}

}  // namespace
}  // namespace woven::test
