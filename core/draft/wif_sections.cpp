#include "wif_sections.h"

#include <cctype>

namespace woven {

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

std::string_view trimmed(std::string_view s) {
    const auto isBlank = [](char c) { return c == ' ' || c == '\t'; };
    while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
    while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
    return s;
}

namespace {

// Calls visit(line, start) for each line of text[begin, end), without its line end (LF, CR LF
// or CR); `start` is where the line begins.
template <class Visit>
void forEachLine(std::string_view text, size_t begin, size_t end, Visit visit) {
    size_t start = begin;
    while (start < end) {
        size_t stop = start;
        while (stop < end && text[stop] != '\n' && text[stop] != '\r') ++stop;
        visit(text.substr(start, stop - start), start);
        start = stop + (stop + 1 < end && text[stop] == '\r' && text[stop + 1] == '\n' ? 2 : 1);
    }
}

bool isBlankOrComment(std::string_view line) {
    line = trimmed(line);
    return line.empty() || line.front() == ';';
}

// The name inside `[ ... ]` at the start of the line; empty when the line is not a header.
std::string_view headerName(std::string_view line) {
    line = trimmed(line);
    if (line.empty() || line.front() != '[') return {};
    const size_t close = line.find(']');
    if (close == std::string_view::npos) return {};
    return trimmed(line.substr(1, close - 1));
}

}  // namespace

WifSections::WifSections(std::string_view text, const std::vector<std::string_view>& wanted) : text_(text) {
    for (std::string_view name : wanted) sections_.push_back(Section{name, {}, 0, 0});
    Body* open = nullptr;  // the body being read, closed by the next header
    bool seenHeader = false;
    int line = 0;
    forEachLine(text, 0, text.size(), [&](std::string_view content, size_t start) {
        ++line;
        const std::string_view name = headerName(content);
        if (name.empty()) {
            if (!seenHeader && !isBlankOrComment(content)) ++linesBeforeFirstSection_;
            return;
        }
        seenHeader = true;
        if (open) open->end = start;
        open = nullptr;
        for (Section& s : sections_)
            if (equalsIgnoringCase(s.name, name)) {
                s.bodies.push_back(Body{start + content.size(), text.size(), line});
                open = &s.bodies.back();
            }
    });
    for (Section& s : sections_)
        for (const Body& body : s.bodies) visitBody(body, [&](const WifEntry&) { ++s.entries; }, &s.strayLines);
}

const WifSections::Section* WifSections::find(std::string_view name) const {
    for (const Section& s : sections_)
        if (equalsIgnoringCase(s.name, name)) return &s;
    return nullptr;
}

int WifSections::entryCount(std::string_view section) const {
    const Section* s = find(section);
    return s ? s->entries : 0;
}

int WifSections::strayLineCount(std::string_view section) const {
    const Section* s = find(section);
    return s ? s->strayLines : 0;
}

int WifSections::headerCount(std::string_view section) const {
    const Section* s = find(section);
    return s ? int(s->bodies.size()) : 0;
}

void WifSections::visitBody(const Body& body, const std::function<void(const WifEntry&)>& visit,
                            int* strayLines) const {
    // The body starts right after its header line's text, so its first "line" is the rest of
    // the header line (empty), numbered as the header.
    int line = body.firstLine - 1;
    forEachLine(text_, body.begin, body.end, [&](std::string_view content, size_t) {
        ++line;
        if (isBlankOrComment(content)) return;
        const size_t equals = content.find('=');
        if (equals == std::string_view::npos) {
            if (strayLines) ++*strayLines;
            return;
        }
        visit(WifEntry{trimmed(content.substr(0, equals)), trimmed(content.substr(equals + 1)), line});
    });
}

void WifSections::forEachEntry(std::string_view section, const std::function<void(const WifEntry&)>& visit) const {
    if (const Section* s = find(section))
        for (const Body& body : s->bodies) visitBody(body, visit, nullptr);
}

std::vector<WifEntry> WifSections::findAll(std::string_view section, std::string_view key) const {
    std::vector<WifEntry> found;
    forEachEntry(section, [&](const WifEntry& e) {
        if (equalsIgnoringCase(e.key, key)) found.push_back(e);
    });
    return found;
}

}  // namespace woven
