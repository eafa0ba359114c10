#include "wif_writer.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

#include "atomic_file.h"
#include "srgb.h"
#include "text_encoding.h"

namespace woven {

namespace {

constexpr const char* kLineEnd = "\r\n";  // WIF is a Windows INI file

glm::ivec3 toBytes(const glm::vec3& linear) {
    glm::ivec3 bytes;
    for (int c = 0; c < 3; ++c) bytes[c] = int(std::lround(linearToSrgb(linear[c]) * 255.0f));
    return bytes;
}

// The shortest text that reads back as the same float.
std::string number(float v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

std::string unitName(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::Decipoints: return "Decipoints";
        case LengthUnit::Inches: return "Inches";
        case LengthUnit::Centimeters: return "Centimeters";
    }
    return "Centimeters";
}

struct Section {
    std::string name, body;
    void add(const std::string& key, const std::string& value) { body += key + "=" + value + kLineEnd; }
};

// The palette as written: the draft's own, then any thread colour it lacks; 1-based indices
// by 8-bit colour, so the threads name the entry that reads back as their colour.
class WrittenPalette {
public:
    explicit WrittenPalette(const Draft& draft) {
        for (const glm::vec3& c : draft.palette) append(c);
        for (const DraftThreads* side : {&draft.warp, &draft.weft})
            for (const glm::vec3& c : side->colors)
                if (!indices_.count(key(c))) append(c);
    }
    int index(const glm::vec3& c) const { return indices_.at(key(c)); }
    const std::vector<glm::ivec3>& colors() const { return colors_; }

private:
    static std::tuple<int, int, int> key(const glm::vec3& c) {
        const glm::ivec3 b = toBytes(c);
        return {b.x, b.y, b.z};
    }
    void append(const glm::vec3& c) {
        colors_.push_back(toBytes(c));
        indices_.emplace(key(c), int(colors_.size()));  // the first entry of a colour wins
    }
    std::vector<glm::ivec3> colors_;
    std::map<std::tuple<int, int, int>, int> indices_;
};

// One property of every thread of a side: the value most threads have becomes the default in
// [WARP] or [WEFT]; the list section is written, with every thread, only when threads differ.
template <class T, class Format>
void addPerThread(Section& side, const char* key, std::vector<Section>& sections, const std::string& listName,
                  const std::vector<T>& values, Format format) {
    if (values.empty()) return;
    std::map<std::string, int> counts;
    for (const T& v : values) ++counts[format(v)];
    auto common = counts.begin();
    for (auto it = counts.begin(); it != counts.end(); ++it)
        if (it->second > common->second) common = it;
    side.add(key, common->first);
    if (counts.size() == 1) return;
    Section list{listName, ""};
    for (size_t i = 0; i < values.size(); ++i) list.add(std::to_string(i + 1), format(values[i]));
    sections.push_back(std::move(list));
}

void addThreads(std::vector<Section>& sections, const std::string& sideName, const DraftThreads& threads,
                const WrittenPalette& palette) {
    Section side{sideName, ""};
    side.add("Threads", std::to_string(threads.count));
    side.add("Units", unitName(threads.units));
    std::vector<Section> lists;
    addPerThread(side, "Color", lists, sideName + " COLORS", threads.colors,
                 [&](const glm::vec3& c) { return std::to_string(palette.index(c)); });
    addPerThread(side, "Spacing", lists, sideName + " SPACING", threads.spacing, number);
    addPerThread(side, "Thickness", lists, sideName + " THICKNESS", threads.thickness, number);
    sections.push_back(std::move(side));
    for (Section& list : lists) sections.push_back(std::move(list));
}

std::string listOf(const IndexSet& set) {
    std::string text;
    for (int i = 0; i < kMaxShafts; ++i)
        if (set[size_t(i)]) text += (text.empty() ? "" : ",") + std::to_string(i + 1);
    return text;
}

// Entries for the non-empty sets; a section whose sets are all empty keeps one "1=0" (none), so
// that it still reads back as present.
void addSets(std::vector<Section>& sections, const std::string& name, const std::vector<IndexSet>& sets) {
    if (sets.empty()) return;
    Section section{name, ""};
    for (size_t i = 0; i < sets.size(); ++i)
        if (sets[i].any()) section.add(std::to_string(i + 1), listOf(sets[i]));
    if (section.body.empty()) section.add("1", "0");
    sections.push_back(std::move(section));
}

}  // namespace

std::string formatWif(const Draft& draft, const std::string& name) {
    validate(draft, name);
    requireInterlacement(draft, name);
    const WrittenPalette palette(draft);

    std::vector<Section> sections;
    if (!draft.title.empty()) {
        sections.push_back({"TEXT", ""});
        sections.back().add("Title", textToUtf8(draft.title));
    }
    Section weaving{"WEAVING", ""};
    weaving.add("Shafts", std::to_string(draft.shafts));
    weaving.add("Treadles", std::to_string(draft.treadles));
    weaving.add("Rising Shed", draft.risingShed ? "true" : "false");
    sections.push_back(std::move(weaving));
    addThreads(sections, "WARP", draft.warp, palette);
    addThreads(sections, "WEFT", draft.weft, palette);
    if (!palette.colors().empty()) {
        Section header{"COLOR PALETTE", ""}, table{"COLOR TABLE", ""};
        header.add("Entries", std::to_string(palette.colors().size()));
        header.add("Form", "RGB");
        header.add("Range", "0,255");
        for (size_t i = 0; i < palette.colors().size(); ++i) {
            const glm::ivec3& c = palette.colors()[i];
            table.add(std::to_string(i + 1), std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z));
        }
        sections.push_back(std::move(header));
        sections.push_back(std::move(table));
    }
    addSets(sections, "THREADING", draft.threading);
    addSets(sections, "TIEUP", draft.tieup);
    addSets(sections, "TREADLING", draft.treadling);
    addSets(sections, "LIFTPLAN", draft.liftplan);

    std::string text = std::string("[WIF]") + kLineEnd;
    // Date and Developers name the WIF specification's version and its authors, as weaving
    // programs write them, not this file.
    for (const char* line : {"Version=1.1", "Date=April 20, 1997", "Developers=wif@mhsoft.com", "Source Program=woven"})
        text += std::string(line) + kLineEnd;
    text += std::string(kLineEnd) + "[CONTENTS]" + kLineEnd;
    for (const Section& s : sections) text += s.name + "=true" + kLineEnd;
    for (const Section& s : sections) text += kLineEnd + ("[" + s.name + "]") + kLineEnd + s.body;
    return text;
}

void writeWif(const std::string& path, const Draft& draft) {
    const std::string text = formatWif(draft, path);
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) throw DraftError("cannot write the file");
    });
}

}  // namespace woven
