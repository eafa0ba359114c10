#pragma once
// A weaving draft as plain data: how the loom is threaded and driven (threading, tie-up,
// treadling or lift plan) and what each warp end and weft pick is (colour, spacing, thickness).
// It is what a WIF file holds (wif_reader.h, wif_writer.h) and what the weave tile and the
// per-thread arrays of the model are made from (draft_tile.h). Shafts, treadles, ends and picks
// are numbered from 0 here; WIF numbers them from 1.
#include <glm/glm.hpp>

#include <bitset>
#include <stdexcept>
#include <string>
#include <vector>

namespace woven {

// Every problem with a draft (a file that cannot be read, a draft that cannot be woven or
// written) throws this, with a message that names the file (and line) where there is one.
struct DraftError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Limits that keep memory bounded whatever a file declares (docs/DRAFTS.md).
constexpr int kMaxDraftThreads = 65536;  // warp ends, and weft picks
constexpr int kMaxShafts = 256;          // shafts, and treadles
constexpr int kMaxPaletteEntries = 65536;

// A set of shafts or of treadles, bit s for number s (from 0).
using IndexSet = std::bitset<kMaxShafts>;

enum class LengthUnit { Decipoints, Inches, Centimeters };
double toCentimeters(double length, LengthUnit unit);

// The warp (one entry per end) or the weft (one per pick). Each per-thread list is either
// empty, when the draft does not say, or holds one value for every thread.
struct DraftThreads {
    int count = 0;
    std::vector<glm::vec3> colors;  // linear RGB
    std::vector<float> spacing;     // centre-to-centre distance to the next thread, in `units`
    std::vector<float> thickness;   // yarn diameter, in `units`
    LengthUnit units = LengthUnit::Centimeters;
};

struct Draft {
    std::string title;  // UTF-8
    int shafts = 0, treadles = 0;
    bool risingShed = true;  // false: the shafts a pick names go down instead of up

    std::vector<IndexSet> threading;  // per end: the shafts it is threaded through (none: never lifted)
    // Each of these is empty when the draft does not have it.
    std::vector<IndexSet> tieup;      // per treadle: the shafts it moves
    std::vector<IndexSet> treadling;  // per pick: the treadles pressed
    std::vector<IndexSet> liftplan;   // per pick: the shafts moved

    std::vector<glm::vec3> palette;  // linear RGB, the colours the threads were chosen from
    DraftThreads warp, weft;

    int ends() const { return warp.count; }
    int picks() const { return weft.count; }
    // Tie-up and treadling, when both are there, decide the sheds; otherwise the lift plan does.
    bool usesTieup() const { return !tieup.empty() && !treadling.empty(); }
    bool hasInterlacement() const { return usesTieup() || !liftplan.empty(); }
};

// Exact equality of every field (a write-then-read round trip gives an equal draft).
bool operator==(const Draft& a, const Draft& b);
inline bool operator!=(const Draft& a, const Draft& b) { return !(a == b); }

// Throws DraftError, prefixed by `name`, when the draft breaks an invariant above: counts out
// of the limits, list sizes that do not match the counts, a shaft or treadle number beyond
// shafts or treadles, colours outside [0, 1], spacing or thickness not positive and finite.
void validate(const Draft& draft, const std::string& name);

// Throws DraftError, prefixed by `name`, saying what is missing when the draft has no
// interlacement (no lift plan, and no tie-up with treadling).
void requireInterlacement(const Draft& draft, const std::string& name);

}  // namespace woven
