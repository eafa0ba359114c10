#include "frame_pattern.h"

#include <cctype>
#include <stdexcept>

namespace woven {

std::optional<FramePattern> FramePattern::parse(const std::string& text) {
    FramePattern pattern;
    bool found = false;
    std::string literal;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            literal += text[i];
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == '%') {
            literal += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        const bool zeroPad = j < text.size() && text[j] == '0';
        if (zeroPad) ++j;
        int width = 0;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) && width < 100)
            width = 10 * width + (text[j++] - '0');
        if (j >= text.size() || text[j] != 'd')
            throw std::invalid_argument(text + ": a frame number field is %d, %4d or %04d (and %% a literal %)");
        if (found) throw std::invalid_argument(text + ": has more than one frame number field");
        found = true;
        pattern.before_ = literal;
        literal.clear();
        pattern.width_ = width;
        pattern.zeroPad_ = zeroPad;
        i = j;
    }
    if (!found) return std::nullopt;
    pattern.after_ = literal;
    return pattern;
}

std::string FramePattern::name(int frame) const {
    std::string digits = std::to_string(frame);
    if (digits.size() < size_t(width_)) digits.insert(0, size_t(width_) - digits.size(), zeroPad_ ? '0' : ' ');
    return withField(digits);
}

std::string FramePattern::withField(const std::string& text) const { return before_ + text + after_; }

}  // namespace woven
