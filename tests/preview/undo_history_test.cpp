// The window's undo history: each completed edit is one step back (however many values changed
// while it was under way), a new edit drops what was undone, and the depth is bounded.
#include <gtest/gtest.h>

#include <string>

#include "undo_history.h"

namespace woven::test {
namespace {

TEST(UndoHistory, StepsBackAndForwardThroughCompletedEdits) {
    UndoHistory<std::string> history;
    history.reset("a");
    EXPECT_FALSE(history.undo("a"));
    history.edited();
    EXPECT_TRUE(history.canUndo());  // an edit under way can be undone once complete
    history.complete("b");
    history.edited();
    history.edited();  // a drag: one edit
    history.complete("c");
    EXPECT_EQ(*history.undo("c"), "b");
    EXPECT_EQ(*history.undo("b"), "a");
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(*history.redo("a"), "b");
    EXPECT_EQ(*history.redo("b"), "c");
    EXPECT_FALSE(history.redo("c"));
}

TEST(UndoHistory, ANewEditDropsWhatWasUndone) {
    UndoHistory<int> history;
    history.reset(1);
    history.edited();
    history.complete(2);
    EXPECT_EQ(*history.undo(2), 1);
    history.edited();
    history.complete(3);  // 1 -> 3
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(*history.undo(3), 1);
}

TEST(UndoHistory, NothingCompletesWithoutAnEdit) {
    UndoHistory<int> history;
    history.reset(1);
    history.complete(2);
    EXPECT_FALSE(history.canUndo());
    history.edited();
    history.reset(5);  // another scene
    EXPECT_FALSE(history.canUndo());
}

TEST(UndoHistory, KeepsItsDepth) {
    UndoHistory<int> history(3);
    history.reset(0);
    for (int i = 1; i <= 10; ++i) {
        history.edited();
        history.complete(i);
    }
    int undone = 0;
    for (int state = 10; std::optional<int> before = history.undo(state); state = *before) ++undone;
    EXPECT_EQ(undone, 3);
}

}  // namespace
}  // namespace woven::test
