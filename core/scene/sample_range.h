#pragma once
// A run of sample indices, the same for every pixel: what a render of part of a frame's samples
// holds (`woven render --first-sample F --spp N` holds first F, count N). Part files carry theirs
// so that `woven merge` can see gaps and overlaps.
#include <string>
#include <vector>

namespace woven {

struct SampleRange {
    int first = 0, count = 0;
    int end() const { return first + count; }  // one past the last
};

// As people count, for messages: "samples 16-31", "sample 7", "samples 0-15, 32-63".
inline std::string describe(const std::vector<SampleRange>& ranges) {
    std::string text;
    for (const SampleRange& r : ranges)
        text += (text.empty() ? "" : ", ") + std::to_string(r.first) +
                (r.count > 1 ? "-" + std::to_string(r.end() - 1) : std::string());
    const bool one = ranges.size() == 1 && ranges.front().count == 1;
    return (one ? "sample " : "samples ") + text;
}
inline std::string describe(const SampleRange& range) { return describe(std::vector<SampleRange>{range}); }

}  // namespace woven
