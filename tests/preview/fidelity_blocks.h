#pragma once
// The fidelity harnesses' subjects and measure of the preview against core (preview_fidelity_test.cpp
// on the flat cloth, scene_fidelity_test.cpp on the shipped scenes and the drape): 8 x 8 block
// means, and the pictures of docs/results/fidelity/.
#include <gtest/gtest.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_description.h"

namespace woven::test {

// What the harnesses show: every fabric of the library ({"preset": name}) and every draft of
// assets/drafts ({"wif": path}, named draft_<stem>), as a material's JSON.
struct FidelitySubject {
    std::string name;
    nlohmann::json material;
};
std::vector<FidelitySubject> fidelitySubjects();

// A harness's case: a subject seen at one of the harness's distances (a struct of its own with a
// `name`), named subject_distance.
template <class Distance>
struct SubjectAt {
    FidelitySubject subject;
    Distance distance;
    std::string name() const { return subject.name + "_" + distance.name; }
};
template <class Distance>
void PrintTo(const SubjectAt<Distance>& c, std::ostream* os) {
    *os << c.name();
}

// Every subject at each of `distances`.
template <class Distance, size_t N>
std::vector<SubjectAt<Distance>> subjectsAt(const Distance (&distances)[N]) {
    std::vector<SubjectAt<Distance>> all;
    for (const FidelitySubject& s : fidelitySubjects())
        for (const Distance& d : distances) all.push_back({s, d});
    return all;
}

// `name` as a test's name: anything but letters and digits as '_'.
std::string testName(std::string name);
template <class Distance>
std::string caseName(const testing::TestParamInfo<SubjectAt<Distance>>& info) {
    return testName(info.param.name());
}

struct BlockErrors {
    double median = 0.0, worst = 0.0;
    size_t blocks = 0;
};

// |preview - core|_1 / (|core|_1 + floor) of each 8 x 8 block wholly in `mask`, the floor 2 % of
// core's mean over those blocks (as relativeError()'s), so near-black blocks are not judged by
// their rounding.
BlockErrors blockErrors(const Image& preview, const Image& core, const std::vector<uint8_t>& mask);

// Over the same blocks, the error core's own noise alone gives a block in expectation: from
// `variance`, each pixel's mean's per channel (RenderPasses::variance), sqrt(2 / pi) times each
// channel's standard deviation of the block's mean, summed, over (|core|_1 + floor).
BlockErrors blockNoise(const Image& core, const Image& variance, const std::vector<uint8_t>& mask);

// With $WOVEN_FIDELITY_PICTURES naming a folder: <name>.png there, the preview beside core's
// image, each its size / `shrink` (1 or 2; tools/preview_fidelity_pictures.sh).
void writeFidelityPicture(const std::string& name, const Image& preview, const Image& core, int shrink);

}  // namespace woven::test
