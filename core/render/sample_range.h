#pragma once
// A run of sample indices, the same for every pixel: what a render of part of a frame's samples
// holds (`woven render --first-sample F --spp N` holds first F, count N). Part files carry theirs
// so that `woven merge` can see gaps and overlaps.
#include <cstdint>
#include <string>
#include <vector>

namespace woven {

// Sample indices are 64-bit, and every range woven makes or reads ends at or below this: the
// "auto" integrator's pilot takes its samples from 2^62 on (render_job.cpp), so no frame repeats
// them, and first + count of a valid range cannot overflow.
constexpr int64_t kSampleIndexLimit = int64_t(1) << 62;

struct SampleRange {
    int64_t first = 0, count = 0;
    int64_t end() const { return first + count; }  // one past the last
};

// Whether [first, first + count) lies within [0, kSampleIndexLimit], checked without overflow.
inline bool withinSampleIndexLimit(int64_t first, int64_t count) {
    return first >= 0 && count >= 0 && count <= kSampleIndexLimit - first;
}

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
