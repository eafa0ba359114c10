#include "status_line.h"

#include <imgui.h>

#include <iostream>

#include "widget_map.h"

namespace woven {

void StatusLine::warn(const std::string& line) {
    std::cerr << "warning: " << line << "\n";
    constexpr size_t kKept = 200;  // a scene of many faults keeps the window's memory bounded
    if (messages_.size() == kKept) messages_.erase(messages_.begin());
    messages_.push_back(line);
}

void StatusLine::draw() {
    // Where it is seen without scrolling: what the last action said.
    if (!text_.empty()) ImGui::TextWrapped("%s", text_.c_str());
    if (messages_.empty()) return;
    const std::string header = "Messages (" + std::to_string(messages_.size()) + ")###messages";
    if (!ui::CollapsingHeader(header.c_str())) return;
    ImGui::PushID("messages");
    for (const std::string& line : messages_) ImGui::TextWrapped("%s", line.c_str());
    if (ui::Button("Clear")) messages_.clear();
    ImGui::PopID();
}

}  // namespace woven
