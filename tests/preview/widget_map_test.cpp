// WidgetMap, the window's record of the widgets it drew, on a real ImGui context: clashes found
// (and said once), scopes and "##" suffixes telling widgets apart, an open combo's box recorded in
// the window it sits in.
#include <gtest/gtest.h>

#include <string>

#include "headless_imgui.h"
#include "widget_map.h"

namespace woven {
namespace {

// One frame drawn into `map`.
template <typename F>
void recordFrame(HeadlessImGui& imgui, WidgetMap& map, F draw, ImVec2 mouse = ImVec2(390, 290), bool down = false) {
    map.beginFrame();
    setCurrentWidgetMap(&map);
    imgui.frame(mouse, down, draw);
    setCurrentWidgetMap(nullptr);
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(WidgetMap, AHeaderAndAButtonOfOneLabelClash) {
    // The window's Render button under its Render header: a click on the button went to the header.
    HeadlessImGui imgui;
    WidgetMap map;
    const auto draw = [] {
        if (ui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) ui::Button("Render");
        ui::Button("Export");
    };
    recordFrame(imgui, map, draw);
    ASSERT_EQ(map.items().size(), 3u);
    const std::vector<WidgetClash> clashes = map.clashes();
    ASSERT_EQ(clashes.size(), 1u);
    EXPECT_EQ(clashes[0].items, (std::vector<size_t>{0, 1}));
    EXPECT_EQ(map.items()[0].kind, "header");
    EXPECT_EQ(map.items()[1].kind, "button");
    // Said on stderr once, however many frames draw it.
    testing::internal::CaptureStderr();
    map.warnClashes();
    recordFrame(imgui, map, draw);
    map.warnClashes();
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(count(said, "ImGui ID clash"), 1u) << said;
    EXPECT_NE(said.find("header \"Render\" in \"panel\", button \"Render\" in \"panel\""), std::string::npos) << said;
}

TEST(WidgetMap, ScopesAndSuffixesSeparateLabels) {
    HeadlessImGui imgui;
    WidgetMap map;
    float a[3] = {}, b[3] = {};
    recordFrame(imgui, map, [&] {
        if (ui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::PushID("render");
            ui::Button("Render");
            ImGui::PopID();
        }
        ui::Button("Save##png");
        ui::Button("Save##exr");
        for (int i = 0; i < 2; ++i) {
            ImGui::PushID(i);
            ui::ColorEdit3("intensity", i == 0 ? a : b);
            ImGui::PopID();
        }
    });
    EXPECT_EQ(map.items().size(), 6u);
    EXPECT_TRUE(map.clashes().empty());
}

TEST(WidgetMap, MultiComponentWidgetsOfOneLabelClash) {
    // Their parts' IDs are made from the label: two of one label share every part.
    HeadlessImGui imgui;
    WidgetMap map;
    int size[2][3] = {};
    recordFrame(imgui, map, [&] {
        ui::InputInt3("size", size[0]);
        ui::InputInt3("size", size[1]);
    });
    EXPECT_EQ(map.clashes().size(), 1u);
}

TEST(WidgetMap, JsonHasEachWidgetsPlace) {
    HeadlessImGui imgui;
    WidgetMap map;
    char text[16] = "1280";
    recordFrame(imgui, map, [&] {
        ui::Button("Render");
        ui::InputText("file", text, sizeof text);
    });
    const nlohmann::json json = map.json();
    ASSERT_EQ(json["items"].size(), 2u);
    const nlohmann::json& field = json["items"][1];
    EXPECT_EQ(field["label"], "file");
    EXPECT_EQ(field["kind"], "input");
    EXPECT_EQ(field["window"], "panel");
    EXPECT_TRUE(field["visible"].get<bool>());
    // The frame (the box that takes a click) starts where the item does and ends before its label.
    EXPECT_EQ(field["frame"][0], field["rect"][0]);
    EXPECT_LT(field["frame"][2].get<float>(), field["rect"][2].get<float>());
    EXPECT_TRUE(json["clashes"].empty());
    EXPECT_TRUE(json["windows"].contains("panel"));
}

// A text field holds a path or a name for a button beside it: typing in it is no value change (it
// hid the final frame and left an empty undo step); a number typed is one.
TEST(WidgetMap, TypingAPathChangesNoValueAndTypingANumberDoes) {
    HeadlessImGui imgui;
    WidgetMap map;
    char path[64] = "";
    int samples = 1;
    int focus = 0;  // 1: the text field, 2: the number field
    const auto draw = [&] {
        if (focus == 1) ImGui::SetKeyboardFocusHere();
        ui::InputText("scene file", path, sizeof path);
        if (focus == 2) ImGui::SetKeyboardFocusHere();
        ui::InputInt("samples", &samples, 0, 0, 0);
    };
    const auto type = [&](int field, char c) {
        focus = field;
        recordFrame(imgui, map, draw);
        focus = 0;
        recordFrame(imgui, map, draw);
        ImGui::GetIO().AddInputCharacter(c);
        recordFrame(imgui, map, draw);
    };
    type(1, 'a');
    EXPECT_STREQ(path, "a");
    EXPECT_EQ(map.valueChanges(), 0u);
    type(2, '7');
    EXPECT_NE(samples, 1);
    EXPECT_GT(map.valueChanges(), 0u);
}

TEST(WidgetMap, AnOpenCombosBoxIsRecordedInItsWindow) {
    HeadlessImGui imgui;
    WidgetMap map;
    int choice = 0;
    const char* names[] = {"path", "bdpt"};
    ImVec2 box;
    const auto draw = [&] {
        if (ui::BeginCombo("integrator", names[choice])) {
            for (int i = 0; i < 2; ++i)
                if (ui::Selectable(names[i], i == choice)) choice = i;
            ui::EndCombo();
        }
        box = itemCentre();
    };
    recordFrame(imgui, map, draw);
    recordFrame(imgui, map, draw, box, false);
    recordFrame(imgui, map, draw, box, true);  // opens it
    recordFrame(imgui, map, draw, box, false);
    ASSERT_EQ(map.items().size(), 3u);
    const WidgetItem& combo = map.items().back();
    EXPECT_EQ(combo.label, "integrator");
    EXPECT_EQ(combo.window, "panel");
    EXPECT_NE(map.items()[0].window, "panel");  // the selectables, in the popup
    EXPECT_TRUE(map.clashes().empty());
}

}  // namespace
}  // namespace woven
