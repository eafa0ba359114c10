#pragma once
// The panel's draft: the draft (WIF) of one woven edit, opened from a file or a scene's material
// or made from the edit's weave, the path its Open and Save use, and the Draft window beside the
// panel that edits it thread by thread (draft_view.h). The draft and the edit it belongs to are
// part of the material's state, which undo brings back (MaterialState).
#include <optional>
#include <string>

#include "draft_editor.h"
#include "draft_view.h"
#include "status_line.h"

namespace woven {

class DraftSection {
public:
    struct State {
        std::optional<DraftEditor> editor;
        int edit = -1;
    };

    // The draft of `edit` is now `editor`, its path `path` (the editor's own where empty); `show`
    // expands the Draft window next frame (a draft the user opened: a scene's own starts collapsed,
    // beside the panel it would hide a third of the view).
    void open(DraftEditor editor, int edit, bool show, const std::string& path = "");
    // No draft for `edit` any more (a weave or a fabric chosen in its place).
    void closeFor(int edit);
    void close() { state_ = {}; }

    // The draft of `edit`, or nullptr where it has none.
    DraftEditor* of(int edit) { return state_.editor && state_.edit == edit ? &*state_.editor : nullptr; }
    bool openFor(int edit) const { return state_.editor && state_.edit == edit; }
    int edit() const { return state_.editor ? state_.edit : -1; }

    const State& state() const { return state_; }
    void restore(State state);

    // The path field's buffer, for its InputText.
    char* path() { return path_; }
    static constexpr size_t kPathSize = 512;
    void setPath(const std::string& path);

    // The Draft window for the draft's edit, whose parameters are `woven`: true where a click
    // changed the draft and `woven` took its weave and thread colours. A failure is `status`'s.
    bool drawWindow(WovenParams& woven, StatusLine& status);

private:
    State state_;
    DraftView view_;
    bool show_ = false;  // expand the Draft window next frame
    char path_[kPathSize] = "draft.wif";
};

}  // namespace woven
