#pragma once
// The INI layer of a WIF file: `[NAME]` section headers wherever they are, `key = value`
// entries, `;` comment lines, LF, CR LF or CR line ends. Section names and keys compare without
// regard to case. Only the sections asked for are indexed, so private sections and text before
// the first header cost nothing; a section that appears twice is read as one. Everything is a
// view into `text`, which must outlive this object.
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace woven {

struct WifEntry {
    std::string_view key, value;  // trimmed of spaces and tabs
    int line;                     // 1-based line number in the file
};

class WifSections {
public:
    // `wanted`: the section names to index, in upper case.
    WifSections(std::string_view text, const std::vector<std::string_view>& wanted);

    // A section counts as present when it has at least one entry.
    bool has(std::string_view section) const { return entryCount(section) > 0; }
    int entryCount(std::string_view section) const;
    // Lines in the section that are neither blank, a comment nor `key=value`.
    int strayLineCount(std::string_view section) const;
    // How many times the section's header appears.
    int headerCount(std::string_view section) const;
    // Lines that are neither blank nor a comment before the first section header.
    int linesBeforeFirstSection() const { return linesBeforeFirstSection_; }

    void forEachEntry(std::string_view section, const std::function<void(const WifEntry&)>& visit) const;
    // Every entry of `section` whose key is `key` (any case), in file order.
    std::vector<WifEntry> findAll(std::string_view section, std::string_view key) const;

private:
    struct Body {
        size_t begin, end;  // byte range after the header line
        int firstLine;
    };
    struct Section {
        std::string_view name;
        std::vector<Body> bodies;
        int entries = 0, strayLines = 0;
    };
    const Section* find(std::string_view name) const;
    void visitBody(const Body& body, const std::function<void(const WifEntry&)>& visit, int* strayLines) const;

    std::string_view text_;
    std::vector<Section> sections_;
    int linesBeforeFirstSection_ = 0;
};

bool equalsIgnoringCase(std::string_view a, std::string_view b);
std::string_view trimmed(std::string_view s);

}  // namespace woven
