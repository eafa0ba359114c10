#include "wif_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <tuple>

#include "drawdown.h"
#include "file_reading.h"
#include "srgb.h"
#include "text_encoding.h"
#include "wif_sections.h"

namespace woven {

namespace {

// The sections the reader uses; [CONTENTS] is not among them, as files do not keep it true.
const std::vector<std::string_view> kKnownSections = {
    "WIF", "TEXT", "WEAVING", "WARP", "WEFT", "COLOR PALETTE", "COLOR TABLE", "THREADING", "TIEUP",
    "TREADLING", "LIFTPLAN", "WARP COLORS", "WEFT COLORS", "WARP SPACING", "WEFT SPACING",
    "WARP THICKNESS", "WEFT THICKNESS"};

// A value without a trailing `; comment`.
std::string_view withoutComment(std::string_view value) {
    return trimmed(value.substr(0, value.find(';')));
}

std::optional<long long> parseInteger(std::string_view s) {
    s = withoutComment(s);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    long long v = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || error != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
}

// A decimal number; one decimal comma is read as a decimal point, as some European programs
// write. Parsed straight to T, so the shortest text of a float reads back as that float.
template <class T = double>
std::optional<T> parseReal(std::string_view s) {
    s = withoutComment(s);
    std::string text(s);
    if (std::count(text.begin(), text.end(), ',') == 1 && text.find('.') == std::string::npos)
        text[text.find(',')] = '.';
    if (!text.empty() && text.front() == '+') text.erase(0, 1);
    T v = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

// The items of a list such as "1,3" or "1 3"; empty items are skipped.
std::vector<std::string_view> listItems(std::string_view value) {
    value = withoutComment(value);
    std::vector<std::string_view> items;
    size_t start = 0;
    for (size_t i = 0; i <= value.size(); ++i) {
        if (i < value.size() && value[i] != ',' && value[i] != ' ' && value[i] != '\t') continue;
        if (i > start) items.push_back(value.substr(start, i - start));
        start = i + 1;
    }
    return items;
}

std::optional<bool> parseBool(std::string_view s) {
    s = withoutComment(s);
    for (const char* yes : {"true", "yes", "on", "1"})
        if (equalsIgnoringCase(s, yes)) return true;
    for (const char* no : {"false", "no", "off", "0"})
        if (equalsIgnoringCase(s, no)) return false;
    return std::nullopt;
}

bool lessColor(const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }
bool lessLength(float a, float b) { return a < b; }

// The value most entries have (the smallest of them on a tie, so the result is deterministic).
template <class T, class Less>
T mostCommon(std::vector<T> values, Less less) {
    std::sort(values.begin(), values.end(), less);
    size_t best = 0, bestRun = 0;
    for (size_t start = 0, end = 0; start < values.size(); start = end) {
        while (end < values.size() && !less(values[start], values[end])) ++end;
        if (end - start > bestRun) best = start, bestRun = end - start;
    }
    return values[best];
}

// "1 entry", "3 entries".
std::string counted(int n, const std::string& noun) {
    const bool y = !noun.empty() && noun.back() == 'y';
    return std::to_string(n) + " " + (n == 1 ? noun : y ? noun.substr(0, noun.size() - 1) + "ies" : noun + "s");
}

// What one section had that could not be used, of one kind: reported as one warning line.
struct Ignored {
    int count = 0, firstLine = 0;
    void add(int line) {
        if (count++ == 0) firstLine = line;
    }
};

class WifReader {
public:
    WifReader(std::string_view text, const std::string& name, std::vector<std::string>& warnings)
        : name_(name), sections_(text, kKnownSections), warnings_(warnings) {}

    Draft read() {
        if (!sections_.has("WIF"))
            fail(sections_.headerCount("WIF") ? "not a WIF file: its [WIF] section is empty"
                                              : "not a WIF file: it has no [WIF] section");
        reportStructure();
        Draft draft;
        draft.title = readTitle();
        readWeaving(draft);
        readPalette(draft);
        draft.warp = readThreads("WARP", draft.ends(), "end", draft.palette);
        draft.weft = readThreads("WEFT", draft.picks(), "pick", draft.palette);
        if (!sections_.has("THREADING")) fail("the draft has no [THREADING]: no warp end is on a shaft");
        const std::string warpThreads = "[WARP] Threads=" + std::to_string(draft.ends());
        const std::string weftThreads = "[WEFT] Threads=" + std::to_string(draft.picks());
        const std::string shafts = "[WEAVING] Shafts=" + std::to_string(draft.shafts);
        const std::string treadles = "[WEAVING] Treadles=" + std::to_string(draft.treadles);
        draft.threading = readSets("THREADING", draft.ends(), warpThreads, draft.shafts, shafts);
        draft.tieup = readSets("TIEUP", draft.treadles, treadles, draft.shafts, shafts);
        draft.treadling = readSets("TREADLING", draft.picks(), weftThreads, draft.treadles, treadles);
        draft.liftplan = readSets("LIFTPLAN", draft.picks(), weftThreads, draft.shafts, shafts);
        requireInterlacement(draft, name_);
        checkLiftplanAgrees(draft);
        return draft;
    }

private:
    [[noreturn]] void fail(const std::string& problem, int line = 0) const {
        throw DraftError(name_ + (line > 0 ? ":" + std::to_string(line) : "") + ": " + problem);
    }
    void warn(const std::string& message) { warnings_.push_back(name_ + ": " + message); }
    // "[SECTION]: 3 <noun>s <what>, first on line 12"
    void warn(std::string_view section, const Ignored& ignored, const std::string& noun, const std::string& what) {
        if (ignored.count == 0) return;
        warn("[" + std::string(section) + "]: " + counted(ignored.count, noun) + " " + what +
             (ignored.count > 1 ? ", first on line " : ", on line ") + std::to_string(ignored.firstLine));
    }

    void reportStructure() {
        if (const int lines = sections_.linesBeforeFirstSection())
            warn(counted(lines, "line") + " of text before the first section ignored");
        for (std::string_view section : kKnownSections) {
            if (const int stray = sections_.strayLineCount(section))
                warn("[" + std::string(section) + "]: " + counted(stray, "line") + " that are not key=value ignored");
            if (sections_.headerCount(section) > 1)
                warn("[" + std::string(section) + "] appears " + std::to_string(sections_.headerCount(section)) +
                     " times; read as one section");
        }
        if (const auto version = value("WIF", "Version"); version && withoutComment(version->value).substr(0, 2) != "1.")
            warn("[WIF] Version=" + std::string(version->value) + " is not 1.x; read as WIF 1.1");
    }

    // The entry `key` of `section`; when it is given more than once, the last one, with a warning.
    std::optional<WifEntry> value(std::string_view section, std::string_view key) {
        const std::vector<WifEntry> found = sections_.findAll(section, key);
        if (found.empty()) return std::nullopt;
        if (found.size() > 1)
            warn("[" + std::string(section) + "] " + std::string(key) + " is given " + std::to_string(found.size()) +
                 " times; the last one (line " + std::to_string(found.back().line) + ") is used");
        return found.back();
    }

    std::string readTitle() {
        const auto title = value("TEXT", "Title");
        return title ? textToUtf8(title->value) : std::string();
    }

    // The highest number among the keys (or the values) of `sections`: what a file that does
    // not declare a count uses.
    long long highestUsed(std::initializer_list<std::string_view> sections, bool keys) const {
        long long highest = 0;
        for (std::string_view section : sections)
            sections_.forEachEntry(section, [&](const WifEntry& e) {
                if (keys) {
                    if (const auto k = parseInteger(e.key)) highest = std::max(highest, *k);
                    return;
                }
                for (std::string_view item : listItems(e.value))
                    if (const auto v = parseInteger(item)) highest = std::max(highest, *v);
            });
        return highest;
    }

    // A declared count, checked against [least, limit] before anything is sized by it. A count
    // the file leaves out is taken from the highest number it uses, with a warning.
    int readCount(std::string_view section, std::string_view key, int least, int limit,
                  const std::function<long long()>& highestUsed) {
        const std::string what = "[" + std::string(section) + "] " + std::string(key);
        const auto entry = value(section, key);
        long long count = 0;
        if (entry) {
            const auto parsed = parseInteger(entry->value);
            if (!parsed) fail(what + "='" + std::string(entry->value) + "' is not a whole number", entry->line);
            count = *parsed;
        } else if ((count = highestUsed()) > 0) {
            warn(what + " is missing; taking " + std::to_string(count) + ", the highest number the draft uses");
        }
        if (count > limit)
            fail(what + "=" + std::to_string(count) + " is more than woven's limit of " + std::to_string(limit),
                 entry ? entry->line : 0);
        if (count < least)
            fail(entry ? what + "=" + std::to_string(count) + " must be at least " + std::to_string(least)
                       : what + " is missing and the draft uses none",
                 entry ? entry->line : 0);
        return int(count);
    }

    void readWeaving(Draft& draft) {
        draft.shafts = readCount("WEAVING", "Shafts", 1, kMaxShafts,
                                 [&] { return highestUsed({"THREADING", "TIEUP", "LIFTPLAN"}, false); });
        draft.treadles = readCount("WEAVING", "Treadles", 0, kMaxShafts, [&] {
            return std::max(highestUsed({"TIEUP"}, true), highestUsed({"TREADLING"}, false));
        });
        draft.warp.count = readCount("WARP", "Threads", 1, kMaxDraftThreads,
                                     [&] { return highestUsed({"THREADING"}, true); });
        draft.weft.count = readCount("WEFT", "Threads", 1, kMaxDraftThreads,
                                     [&] { return highestUsed({"TREADLING", "LIFTPLAN"}, true); });
        if (const auto rising = value("WEAVING", "Rising Shed")) {
            const auto parsed = parseBool(rising->value);
            if (parsed) draft.risingShed = *parsed;
            else warn("[WEAVING] Rising Shed='" + std::string(rising->value) + "' is not yes or no (line " +
                      std::to_string(rising->line) + "); a rising shed is assumed");
        }
    }

    // [COLOR PALETTE] and [COLOR TABLE]: sRGB colours on the scale Range (default 0..255),
    // stored linear. Entries the table does not define are black and cannot be used by threads.
    void readPalette(Draft& draft) {
        const int entries = readCount("COLOR PALETTE", "Entries", 0, kMaxPaletteEntries,
                                      [&] { return highestUsed({"COLOR TABLE"}, true); });
        if (const auto form = value("COLOR PALETTE", "Form"); form && !equalsIgnoringCase(withoutComment(form->value), "RGB"))
            warn("[COLOR PALETTE] Form=" + std::string(form->value) + " is not RGB; the colours are read as RGB");
        double low = 0, high = 255;
        if (const auto range = value("COLOR PALETTE", "Range")) {
            const std::vector<std::string_view> items = listItems(range->value);
            std::optional<double> a, b;
            if (items.size() == 2) a = parseReal(items[0]), b = parseReal(items[1]);
            if (!a || !b || !(*b > *a))
                fail("[COLOR PALETTE] Range='" + std::string(range->value) + "' is not 'low,high' with high > low",
                     range->line);
            low = *a, high = *b;
        }
        draft.palette.assign(size_t(entries), glm::vec3(0.0f));
        paletteDefined_.assign(size_t(entries), false);
        Ignored malformed, beyond, clamped;
        sections_.forEachEntry("COLOR TABLE", [&](const WifEntry& e) {
            const auto index = parseInteger(e.key);
            const std::vector<std::string_view> items = listItems(e.value);
            std::optional<double> rgb[3];
            if (items.size() == 3)
                for (int c = 0; c < 3; ++c) rgb[c] = parseReal(items[size_t(c)]);
            if (!index || !rgb[0] || !rgb[1] || !rgb[2]) return malformed.add(e.line);
            if (*index < 1 || *index > entries) return beyond.add(e.line);
            glm::vec3& color = draft.palette[size_t(*index - 1)];
            bool outside = false;
            for (int c = 0; c < 3; ++c) {
                const double unit = (*rgb[c] - low) / (high - low);
                outside = outside || unit < 0.0 || unit > 1.0;
                color[c] = srgbToLinear(float(std::clamp(unit, 0.0, 1.0)));
            }
            if (outside) clamped.add(e.line);
            paletteDefined_[size_t(*index - 1)] = true;
        });
        warn("COLOR TABLE", malformed, "entry", "ignored: not 'index=r,g,b'");
        warn("COLOR TABLE", beyond, "entry",
             "ignored: numbered outside 1.." + std::to_string(entries) + " ([COLOR PALETTE] Entries)");
        warn("COLOR TABLE", clamped, "colour", "clamped to the Range");
    }

    // One value per thread: the section [<SIDE> <LIST>] overrides the default `key` of [<SIDE>].
    // `parse` returns nothing for a value it cannot use, after counting it in `bad` or `beyond`.
    template <class T>
    std::vector<std::optional<T>> readPerThread(
        const std::string& side, std::string_view key, const std::string& list, int count,
        const std::function<std::optional<T>(std::string_view, Ignored& bad, Ignored& beyond, int line)>& parse,
        const std::string& beyondWhat) {
        std::optional<T> fallback;
        Ignored bad, beyond;
        if (const auto entry = value(side, key)) fallback = parse(entry->value, bad, beyond, entry->line);
        warn(side, bad, std::string(key) + " value", "ignored: cannot be read");
        warn(side, beyond, std::string(key) + " value", "ignored: " + beyondWhat);
        std::vector<std::optional<T>> values(size_t(count), fallback);
        const std::string section = side + " " + list;
        Ignored badKey, keyBeyond;
        bad = beyond = Ignored();
        sections_.forEachEntry(section, [&](const WifEntry& e) {
            const auto index = parseInteger(e.key);
            if (!index) return badKey.add(e.line);
            if (*index < 1 || *index > count) return keyBeyond.add(e.line);
            if (auto v = parse(e.value, bad, beyond, e.line)) values[size_t(*index - 1)] = v;
        });
        warn(section, badKey, "entry", "ignored: the key is not a thread number");
        warn(section, keyBeyond, "entry",
             "ignored: numbered outside 1.." + std::to_string(count) + " ([" + side + "] Threads)");
        warn(section, bad, "value", "ignored: cannot be read");
        warn(section, beyond, "value", "ignored: " + beyondWhat);
        return values;
    }

    // Either every thread has a value or none has (the draft does not say): threads left
    // without one take the value most of the others have, with a warning.
    template <class T, class Less>
    std::vector<T> everyThreadOrNone(const std::vector<std::optional<T>>& values, Less less, const std::string& side,
                                     const char* threadName, const char* what) {
        std::vector<T> given;
        for (const auto& v : values)
            if (v) given.push_back(*v);
        if (given.empty()) return {};
        if (given.size() == values.size()) return given;
        const T common = mostCommon(given, less);
        std::vector<T> all;
        for (const auto& v : values) all.push_back(v ? *v : common);
        warn("[" + side + "]: " + counted(int(values.size() - given.size()), threadName) + " without a " + what +
             ": given the " + what + " most of the other " + threadName + "s have");
        return all;
    }

    DraftThreads readThreads(const std::string& side, int count, const char* threadName,
                             const std::vector<glm::vec3>& palette) {
        DraftThreads threads;
        threads.count = count;
        const int paletteSize = int(palette.size());
        const auto color = [&](std::string_view text, Ignored& bad, Ignored& beyond, int line) -> std::optional<glm::vec3> {
            const auto index = parseInteger(text);
            if (!index || *index < 0) return bad.add(line), std::nullopt;
            if (*index == 0) return std::nullopt;  // 0: no colour
            if (*index > paletteSize || !paletteDefined_[size_t(*index - 1)]) return beyond.add(line), std::nullopt;
            return palette[size_t(*index - 1)];
        };
        const auto length = [](std::string_view text, Ignored& bad, Ignored&, int line) -> std::optional<float> {
            const auto v = parseReal<float>(text);
            if (!v || !(*v > 0.0f)) return bad.add(line), std::nullopt;
            return *v;
        };
        const std::string notInPalette = "names no colour of [COLOR TABLE]";
        threads.colors = everyThreadOrNone(
            readPerThread<glm::vec3>(side, "Color", "COLORS", count, color, notInPalette), lessColor, side,
            threadName, "colour");
        threads.spacing = everyThreadOrNone(readPerThread<float>(side, "Spacing", "SPACING", count, length, ""),
                                            lessLength, side, threadName, "spacing");
        threads.thickness = everyThreadOrNone(readPerThread<float>(side, "Thickness", "THICKNESS", count, length, ""),
                                              lessLength, side, threadName, "thickness");
        threads.units = readUnits(side, !threads.spacing.empty() || !threads.thickness.empty());
        return threads;
    }

    LengthUnit readUnits(const std::string& side, bool needed) {
        const auto units = value(side, "Units");
        if (!units) {
            if (needed) warn("[" + side + "] has no Units; spacing and thickness are read as centimeters");
            return LengthUnit::Centimeters;
        }
        const std::string_view text = withoutComment(units->value);
        if (equalsIgnoringCase(text, "decipoints")) return LengthUnit::Decipoints;
        if (equalsIgnoringCase(text, "inches")) return LengthUnit::Inches;
        if (equalsIgnoringCase(text, "centimeters") || equalsIgnoringCase(text, "centimetres"))
            return LengthUnit::Centimeters;
        warn("[" + side + "] Units=" + std::string(units->value) + " (line " + std::to_string(units->line) +
             ") is not Decipoints, Inches or Centimeters; read as centimeters");
        return LengthUnit::Centimeters;
    }

    // An index section: keys numbered 1..keyCount (threads or treadles), values lists of numbers
    // 1..valueCount (shafts or treadles), 0 meaning none. Empty when the section is absent.
    std::vector<IndexSet> readSets(std::string_view section, int keyCount, const std::string& keyLimit,
                                   int valueCount, const std::string& valueLimit) {
        if (!sections_.has(section)) return {};
        std::vector<IndexSet> sets(static_cast<size_t>(keyCount));
        std::vector<bool> seen(size_t(keyCount), false);
        Ignored badKey, keyBeyond, repeated, badValue, valueBeyond;
        sections_.forEachEntry(section, [&](const WifEntry& e) {
            const auto key = parseInteger(e.key);
            if (!key) return badKey.add(e.line);
            if (*key < 1 || *key > keyCount) return keyBeyond.add(e.line);
            const size_t index = size_t(*key - 1);
            if (seen[index]) repeated.add(e.line);
            seen[index] = true;
            sets[index].reset();
            for (std::string_view item : listItems(e.value)) {
                const auto v = parseInteger(item);
                if (!v || *v < 0) badValue.add(e.line);
                else if (*v > valueCount) valueBeyond.add(e.line);
                else if (*v > 0) sets[index].set(size_t(*v - 1));
            }
        });
        const std::string name(section);
        warn(name, badKey, "entry", "ignored: the key is not a number");
        warn(name, keyBeyond, "entry", "ignored: numbered outside 1.." + std::to_string(keyCount) + " (" + keyLimit + ")");
        warn(name, badValue, "value", "ignored: not a whole number >= 0");
        warn(name, valueBeyond, "value", "ignored: beyond " + valueLimit);
        warn(name, repeated, "repeated number", "(the last entry for each is used)");
        return sets;
    }

    // Files often hold both; when they disagree, say which one was used.
    void checkLiftplanAgrees(const Draft& draft) {
        if (!draft.usesTieup() || draft.liftplan.empty()) return;
        int differing = 0;
        for (int pick = 0; pick < draft.picks(); ++pick) differing += shedOf(draft, pick) != draft.liftplan[size_t(pick)];
        if (differing)
            warn("[LIFTPLAN] differs from [TIEUP] x [TREADLING] in " + counted(differing, "pick") +
                 "; the tie-up and treadling are used");
    }

    const std::string& name_;
    WifSections sections_;
    std::vector<std::string>& warnings_;
    std::vector<bool> paletteDefined_;
};

}  // namespace

Draft parseWif(std::string_view text, const std::string& name, std::vector<std::string>& warnings) {
    if (text.size() > kMaxWifFileBytes)
        throw DraftError(name + ": larger than woven's limit of " + std::to_string(kMaxWifFileBytes >> 20) + " MiB for a WIF file");
    if (text.find('\0') != std::string_view::npos)
        throw DraftError(name + ": not a WIF file: it holds NUL bytes (binary data, or UTF-16 text)");
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
    return WifReader(text, name, warnings).read();
}

Draft readWif(const std::string& path, std::vector<std::string>& warnings) {
    std::vector<unsigned char> bytes;
    try {
        bytes = readRegularFile(path, kMaxWifFileBytes);
    } catch (const FileReadError& e) {
        throw DraftError(e.what());
    }
    return parseWif(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path, warnings);
}

}  // namespace woven
