#pragma once
// A file name with one printf-style field for a frame number: "shot_%04d.json" names frame 7
// "shot_0007.json". `woven submit --frames A..B` takes the scene and output of every frame from
// such patterns.
#include <optional>
#include <string>

namespace woven {

class FramePattern {
public:
    // The pattern in `text`: one field %d, %Nd or %0Nd, and %% for a literal %. Nothing when
    // `text` has no field; throws std::invalid_argument when it has two, or another % sequence.
    static std::optional<FramePattern> parse(const std::string& text);

    std::string name(int frame) const;                     // the field replaced by frame (>= 0)
    std::string withField(const std::string& text) const;  // ... by `text`

private:
    std::string before_, after_;
    int width_ = 0;
    bool zeroPad_ = false;
};

}  // namespace woven
