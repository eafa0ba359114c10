#pragma once
// The window's draft view, laid out as weaving programs draw a draft: the threading above the
// drawdown with shaft 1 nearest it, the tie-up to its right, the treadling (or the lift plan)
// beside the drawdown, warp colours above the threading and weft colours right of the
// treadling. End 1 is on the left and pick 1 at the top, as the cloth shows them (docs/DRAFTS.md).
// DraftLayout is where everything is and what a click hits, without ImGui, so tests can click;
// DraftView draws it with ImGui and turns clicks into DraftEditor edits.
#include <glm/glm.hpp>

#include <vector>

#include "draft_editor.h"

namespace woven {

class DraftLayout {
public:
    enum class Region { None, WarpColors, Threading, Tieup, Treadling, Liftplan, Drawdown, WeftColors };
    // A block of cells: `columns` x `rows` cells of the layout's size from `origin` (pixels, y down).
    struct Grid {
        Region region;
        glm::vec2 origin;
        int columns, rows;
    };
    // A cell: (column, row) of a region's grid.
    struct Hit {
        Region region = Region::None;
        int column = 0, row = 0;
    };

    DraftLayout(const Draft& draft, float cellPixels);

    const std::vector<Grid>& grids() const { return grids_; }
    float cell() const { return cell_; }
    glm::vec2 size() const { return size_; }
    // What a point (pixels from the layout's origin) is on.
    Hit hit(const glm::vec2& point) const;

    // The shaft of a threading, tie-up or lift plan cell: shaft 1 is the threading's and the
    // tie-up's bottom row, the lift plan's left column.
    int shaftOf(const Hit& hit) const;

private:
    std::vector<Grid> grids_;
    float cell_;
    int shafts_;
    glm::vec2 size_{0.0f};
};

// Which thread's colour the picker edits.
struct ThreadSelection {
    DraftSide side = DraftSide::Warp;
    int thread = -1;  // none
};

// What a click on `hit` does: toggles a threading, tie-up, treadling or lift plan cell, or
// selects the thread of a colour bar (or, on the drawdown, the end there). Returns true when the
// draft changed.
bool applyClick(DraftEditor& editor, const DraftLayout& layout, const DraftLayout::Hit& hit, ThreadSelection& selection);

class DraftView {
public:
    // Draws the view into the current ImGui window, with the colour picker for the selected
    // thread or stripe; `warpColor` / `weftColor`: the material's colours, shown for threads
    // the draft gives none. Returns true when the draft changed.
    bool draw(DraftEditor& editor, const glm::vec3& warpColor, const glm::vec3& weftColor);

private:
    float cell_ = 10.0f;
    ThreadSelection selection_;
    bool wholeStripe_ = true;
};

}  // namespace woven
