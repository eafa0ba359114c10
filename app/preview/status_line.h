#pragma once
// What every section of the previewer's panel reports to: the status line (what the last action
// said, or why it failed) and the Messages (the warnings the commands print on stderr, kept where
// the window's user sees them).
#include <algorithm>
#include <exception>
#include <string>
#include <vector>

namespace woven {

class StatusLine {
public:
    void say(std::string line) { text_ = std::move(line); }
    const std::string& text() const { return text_; }

    // A warning: on stderr as the commands print it, and in the Messages.
    void warn(const std::string& line);
    // The warnings of a scene just opened (printed on stderr as it was read) in place of the last.
    void restartMessages(std::vector<std::string> warnings) { messages_ = std::move(warnings); }
    const std::vector<std::string>& messages() const { return messages_; }

    // Runs `step`; an exception it throws becomes the status line. Returns whether none was thrown.
    template <typename Step>
    bool attempt(Step&& step) {
        try {
            step();
            return true;
        } catch (const std::exception& e) {
            text_ = e.what();
            return false;
        }
    }

    // The status line, then the Messages collapsed under a header that counts them.
    void draw();

private:
    std::string text_;
    std::vector<std::string> messages_;  // oldest first
};

// `value` within [lo, hi], the status line saying so when it was not.
template <typename T>
void clampSetting(StatusLine& status, const char* name, T& value, T lo, T hi) {
    const T clamped = std::clamp(value, lo, hi);
    if (clamped == value) return;
    status.say(std::string(name) + " " + std::to_string(value) + " is out of range " + std::to_string(lo) + ".." +
               std::to_string(hi) + ": " + std::to_string(clamped) + " instead");
    value = clamped;
}

}  // namespace woven
