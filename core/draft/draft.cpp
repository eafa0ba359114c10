#include "draft.h"

#include <cmath>

namespace woven {

double toCentimeters(double length, LengthUnit unit) {
    switch (unit) {
        case LengthUnit::Decipoints: return length * 2.54 / 720.0;  // a tenth of a 1/72 inch point
        case LengthUnit::Inches: return length * 2.54;
        case LengthUnit::Centimeters: return length;
    }
    return length;
}

namespace {

bool sameThreads(const DraftThreads& a, const DraftThreads& b) {
    return a.count == b.count && a.colors == b.colors && a.spacing == b.spacing &&
           a.thickness == b.thickness && a.units == b.units;
}

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw DraftError(name + ": " + problem);
}

void checkSets(const std::vector<IndexSet>& sets, const char* what, size_t expectedSize, bool optional,
               int members, const char* memberName, const std::string& name) {
    if (!(optional && sets.empty()) && sets.size() != expectedSize)
        fail(name, std::string(what) + " has " + std::to_string(sets.size()) + " entries, expected " +
                       std::to_string(expectedSize));
    for (size_t i = 0; i < sets.size(); ++i)
        if ((sets[i] >> members).any())
            fail(name, std::string(what) + " entry " + std::to_string(i + 1) + " names a " + memberName +
                           " beyond the " + std::to_string(members) + " there are");
}

void checkThreads(const DraftThreads& threads, const char* side, const std::string& name) {
    const std::string where = std::string(side) + ": ";
    if (threads.count < 1 || threads.count > kMaxDraftThreads)
        fail(name, where + "thread count " + std::to_string(threads.count) + " is outside 1.." +
                       std::to_string(kMaxDraftThreads));
    auto checkSize = [&](size_t size, const char* list) {
        if (size != 0 && size != size_t(threads.count))
            fail(name, where + std::to_string(size) + " " + list + " for " + std::to_string(threads.count) + " threads");
    };
    checkSize(threads.colors.size(), "colours");
    checkSize(threads.spacing.size(), "spacings");
    checkSize(threads.thickness.size(), "thicknesses");
    for (const glm::vec3& c : threads.colors)
        for (int k = 0; k < 3; ++k)
            if (!(c[k] >= 0.0f && c[k] <= 1.0f)) fail(name, where + "a colour component is outside [0, 1]");
    for (const auto* lengths : {&threads.spacing, &threads.thickness})
        for (float v : *lengths)
            if (!(std::isfinite(v) && v > 0.0f)) fail(name, where + "a spacing or thickness is not positive and finite");
}

}  // namespace

bool operator==(const Draft& a, const Draft& b) {
    return a.title == b.title && a.shafts == b.shafts && a.treadles == b.treadles &&
           a.risingShed == b.risingShed && a.threading == b.threading && a.tieup == b.tieup &&
           a.treadling == b.treadling && a.liftplan == b.liftplan && a.palette == b.palette &&
           sameThreads(a.warp, b.warp) && sameThreads(a.weft, b.weft);
}

void validate(const Draft& draft, const std::string& name) {
    if (draft.shafts < 1 || draft.shafts > kMaxShafts)
        fail(name, "shaft count " + std::to_string(draft.shafts) + " is outside 1.." + std::to_string(kMaxShafts));
    if (draft.treadles < 0 || draft.treadles > kMaxShafts)
        fail(name, "treadle count " + std::to_string(draft.treadles) + " is outside 0.." + std::to_string(kMaxShafts));
    checkThreads(draft.warp, "warp", name);
    checkThreads(draft.weft, "weft", name);
    checkSets(draft.threading, "threading", size_t(draft.ends()), false, draft.shafts, "shaft", name);
    checkSets(draft.tieup, "tie-up", size_t(draft.treadles), true, draft.shafts, "shaft", name);
    checkSets(draft.treadling, "treadling", size_t(draft.picks()), true, draft.treadles, "treadle", name);
    checkSets(draft.liftplan, "lift plan", size_t(draft.picks()), true, draft.shafts, "shaft", name);
    if (draft.palette.size() > size_t(kMaxPaletteEntries))
        fail(name, "the palette has more than " + std::to_string(kMaxPaletteEntries) + " colours");
    for (const glm::vec3& c : draft.palette)
        for (int k = 0; k < 3; ++k)
            if (!(c[k] >= 0.0f && c[k] <= 1.0f)) fail(name, "a palette colour component is outside [0, 1]");
}

void requireInterlacement(const Draft& draft, const std::string& name) {
    if (draft.hasInterlacement()) return;
    std::string missing = "no [LIFTPLAN], and ";
    if (draft.tieup.empty() && draft.treadling.empty()) missing += "no [TIEUP] or [TREADLING]";
    else missing += draft.tieup.empty() ? "a [TREADLING] without a [TIEUP]" : "a [TIEUP] without a [TREADLING]";
    fail(name, "the draft has no interlacement: " + missing);
}

}  // namespace woven
