#include "draft_view.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "drawdown.h"
#include "srgb.h"
#include "display_transform.h"

namespace woven {

DraftLayout::DraftLayout(const Draft& draft, float cellPixels) : cell_(cellPixels), shafts_(draft.shafts) {
    const int ends = draft.ends(), picks = draft.picks(), shafts = draft.shafts;
    const bool tieup = draft.usesTieup();
    const int right = tieup ? draft.treadles : shafts;  // columns beside the drawdown
    const float c = cellPixels;
    const float below = float(shafts + 3) * c;         // the drawdown's top
    const float beside = float(ends + 1) * c;          // the right-hand blocks' left
    grids_.push_back({Region::WarpColors, {0.0f, 0.0f}, ends, 1});
    grids_.push_back({Region::Threading, {0.0f, 2.0f * c}, ends, shafts});
    if (tieup) grids_.push_back({Region::Tieup, {beside, 2.0f * c}, draft.treadles, shafts});
    grids_.push_back({Region::Drawdown, {0.0f, below}, ends, picks});
    grids_.push_back({tieup ? Region::Treadling : Region::Liftplan, {beside, below}, right, picks});
    grids_.push_back({Region::WeftColors, {beside + float(right + 1) * c, below}, 1, picks});
    size_ = glm::vec2(float(ends + right + 3) * c, below + float(picks) * c);
}

DraftLayout::Hit DraftLayout::hit(const glm::vec2& point) const {
    for (const Grid& g : grids_) {
        const glm::vec2 cellPosition = (point - g.origin) / cell_;
        const int column = int(std::floor(cellPosition.x)), row = int(std::floor(cellPosition.y));
        if (column >= 0 && column < g.columns && row >= 0 && row < g.rows) return {g.region, column, row};
    }
    return {};
}

int DraftLayout::shaftOf(const Hit& hit) const {
    return hit.region == Region::Liftplan ? hit.column : shafts_ - 1 - hit.row;
}

bool applyClick(DraftEditor& editor, const DraftLayout& layout, const DraftLayout::Hit& hit, ThreadSelection& selection) {
    using Region = DraftLayout::Region;
    switch (hit.region) {
        case Region::Threading: editor.toggleThreading(hit.column, layout.shaftOf(hit)); return true;
        case Region::Tieup: editor.toggleTieup(hit.column, layout.shaftOf(hit)); return true;
        case Region::Treadling: editor.toggleTreadling(hit.row, hit.column); return true;
        case Region::Liftplan: editor.toggleLiftplan(hit.row, layout.shaftOf(hit)); return true;
        case Region::WarpColors: selection = {DraftSide::Warp, hit.column}; return false;
        case Region::WeftColors: selection = {DraftSide::Weft, hit.row}; return false;
        case Region::Drawdown:
            selection = editor.warpOnTop(hit.column, hit.row) ? ThreadSelection{DraftSide::Warp, hit.column}
                                                                : ThreadSelection{DraftSide::Weft, hit.row};
            return false;
        case Region::None: return false;
    }
    return false;
}

namespace {

// Linear RGB as the display shows it: ImGui draws bytes as sRGB.
ImU32 displayColor(const glm::vec3& linear) {
    auto byte = [](float c) { return int(std::lround(linearToSrgb(std::clamp(c, 0.0f, 1.0f)) * 255.0f)); };
    return IM_COL32(byte(linear.r), byte(linear.g), byte(linear.b), 255);
}

const ImU32 kRaised = IM_COL32(30, 30, 30, 255), kLowered = IM_COL32(225, 225, 225, 255);

}  // namespace

bool DraftView::draw(DraftEditor& editor, const glm::vec3& warpColor, const glm::vec3& weftColor) {
    const Draft& d = editor.draft();
    bool changed = false;
    ImGui::Text("%s: %d ends, %d picks, %d shafts, %s", editor.name().empty() ? "(unsaved)" : editor.name().c_str(),
                d.ends(), d.picks(), d.shafts, d.usesTieup() ? "tie-up and treadling" : "lift plan");
    ImGui::SliderFloat("cell pixels", &cell_, 4.0f, 24.0f, "%.0f");
    int counts[2] = {d.ends(), d.picks()};
    if (ImGui::InputInt2("ends, picks", counts, ImGuiInputTextFlags_EnterReturnsTrue)) {
        editor.setThreadCount(DraftSide::Warp, std::clamp(counts[0], 1, kMaxDraftThreads));
        editor.setThreadCount(DraftSide::Weft, std::clamp(counts[1], 1, kMaxDraftThreads));
        changed = true;
    }

    // The colour of the selected thread, or of its stripe, edited as sRGB like a weaving program.
    const int count = selection_.side == DraftSide::Warp ? d.ends() : d.picks();
    if (selection_.thread >= 0 && selection_.thread < count) {
        const bool warp = selection_.side == DraftSide::Warp;
        const glm::vec3& unset = warp ? warpColor : weftColor;
        const auto [first, last] = editor.stripe(selection_.side, selection_.thread);
        ImGui::Text("%s %d (stripe %d-%d)", warp ? "end" : "pick", selection_.thread + 1, first + 1, last + 1);
        ImGui::SameLine();
        ImGui::Checkbox("whole stripe", &wholeStripe_);
        const glm::vec3 linear = editor.color(selection_.side, selection_.thread, unset);
        glm::vec3 srgb(linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b));
        if (ImGui::ColorEdit3("colour (sRGB)", &srgb.x)) {
            const glm::vec3 c(srgbToLinear(srgb.r), srgbToLinear(srgb.g), srgbToLinear(srgb.b));
            if (wholeStripe_) editor.setStripeColor(selection_.side, selection_.thread, c, unset);
            else editor.setColor(selection_.side, selection_.thread, c, unset);
            changed = true;
        }
    } else {
        ImGui::TextDisabled("click a cell to toggle it, a colour bar or the drawdown to pick a thread's colour");
    }

    const DraftLayout layout(d, cell_);
    ImGui::BeginChild("draft cells", ImVec2(0.0f, 0.0f), true, ImGuiWindowFlags_HorizontalScrollbar);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("cells", ImVec2(layout.size().x, layout.size().y));
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        changed |= applyClick(editor, layout, layout.hit({mouse.x - origin.x, mouse.y - origin.y}), selection_);
    }
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 clipMin = list->GetClipRectMin(), clipMax = list->GetClipRectMax();
    const float c = layout.cell(), gap = c >= 6.0f ? 1.0f : 0.0f;
    const Drawdown drawdown(d, editor.name());
    for (const DraftLayout::Grid& g : layout.grids()) {
        const glm::vec2 o(origin.x + g.origin.x, origin.y + g.origin.y);
        // Only the cells in view: a draft of thousands of threads stays cheap to draw.
        const int c0 = std::max(0, int((clipMin.x - o.x) / c)), c1 = std::min(g.columns, int((clipMax.x - o.x) / c) + 1);
        const int r0 = std::max(0, int((clipMin.y - o.y) / c)), r1 = std::min(g.rows, int((clipMax.y - o.y) / c) + 1);
        for (int r = r0; r < r1; ++r)
            for (int col = c0; col < c1; ++col) {
                const DraftLayout::Hit cell{g.region, col, r};
                ImU32 color = kLowered;
                switch (g.region) {
                    case DraftLayout::Region::WarpColors: color = displayColor(editor.color(DraftSide::Warp, col, warpColor)); break;
                    case DraftLayout::Region::WeftColors: color = displayColor(editor.color(DraftSide::Weft, r, weftColor)); break;
                    case DraftLayout::Region::Threading: if (d.threading[size_t(col)][size_t(layout.shaftOf(cell))]) color = kRaised; break;
                    case DraftLayout::Region::Tieup: if (d.tieup[size_t(col)][size_t(layout.shaftOf(cell))]) color = kRaised; break;
                    case DraftLayout::Region::Treadling: if (d.treadling[size_t(r)][size_t(col)]) color = kRaised; break;
                    case DraftLayout::Region::Liftplan: if (d.liftplan[size_t(r)][size_t(col)]) color = kRaised; break;
                    case DraftLayout::Region::Drawdown: {
                        color = displayColor(drawdown.warpOnTop(col, r) ? editor.color(DraftSide::Warp, col, warpColor)
                                                  : editor.color(DraftSide::Weft, r, weftColor));
                        break;
                    }
                    case DraftLayout::Region::None: break;
                }
                const ImVec2 lo(o.x + float(col) * c, o.y + float(r) * c);
                list->AddRectFilled(lo, ImVec2(lo.x + c - gap, lo.y + c - gap), color);
            }
    }
    // The selected thread's colour cell, outlined.
    if (selection_.thread >= 0 && selection_.thread < count)
        for (const DraftLayout::Grid& g : layout.grids()) {
            const bool warpBar = g.region == DraftLayout::Region::WarpColors && selection_.side == DraftSide::Warp;
            const bool weftBar = g.region == DraftLayout::Region::WeftColors && selection_.side == DraftSide::Weft;
            if (!warpBar && !weftBar) continue;
            const ImVec2 lo(origin.x + g.origin.x + (warpBar ? float(selection_.thread) * c : 0.0f),
                            origin.y + g.origin.y + (weftBar ? float(selection_.thread) * c : 0.0f));
            list->AddRect(ImVec2(lo.x - 1.0f, lo.y - 1.0f), ImVec2(lo.x + c, lo.y + c), IM_COL32(255, 200, 0, 255), 0.0f, 0, 2.0f);
        }
    ImGui::EndChild();
    return changed;
}

}  // namespace woven
