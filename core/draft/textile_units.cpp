#include "textile_units.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "short_number.h"

namespace woven {

namespace {

// The finest silks have about 200 threads per cm; beyond this a count is a typing mistake. Below
// a thread a metre the repeat is past any cloth, and its cover and weight no numbers (inf, nan).
constexpr double kMinThreadsPerCm = 0.01, kMaxThreadsPerCm = 1000.0;
// Yarn counts from a single fine filament to a rope: woven's bounds in tex.
constexpr double kMinTex = 0.01, kMaxTex = 10000.0;

std::string q(const std::string& key) { return "'" + key + "'"; }

// One side's thread count from "<side>_per_cm" or "<side>_per_inch", in threads per cm.
std::optional<double> threadsPerCm(const nlohmann::json& j, const std::string& side) {
    const std::string cm = side + "_per_cm", inch = side + "_per_inch";
    if (j.contains(cm) && j.contains(inch)) throw std::invalid_argument(q(cm) + " and " + q(inch) + " both give the " + side + ": give one");
    const std::string& key = j.contains(cm) ? cm : inch;
    if (!j.contains(key)) return std::nullopt;
    const double perUnit = j[key].is_number() ? j[key].get<double>() : NAN;
    const double perCm = key == inch ? perUnit / kCmPerInch : perUnit;
    if (!(perCm >= kMinThreadsPerCm && perCm <= kMaxThreadsPerCm))
        throw std::invalid_argument(q(key) + " = " + j[key].dump() + ": need a number of threads from " +
                                    shortNumber(kMinThreadsPerCm) + " to " + shortNumber(kMaxThreadsPerCm) + " per cm (" +
                                    shortNumber(kMinThreadsPerCm * kCmPerInch) + " to " +
                                    shortNumber(kMaxThreadsPerCm * kCmPerInch) + " per inch)");
    return perCm;
}

}  // namespace

const std::vector<Fibre>& fibres() {
    static const std::vector<Fibre> table = {
        {"cotton", 1.52}, {"linen", 1.50}, {"wool", 1.31},  {"silk", 1.34},
        {"viscose", 1.52}, {"polyester", 1.38}, {"nylon", 1.14}, {"acrylic", 1.18},
    };
    return table;
}

const std::vector<const char*>& textileKeyNames() {
    static const std::vector<const char*> names = {"ends_per_cm", "picks_per_cm", "ends_per_inch", "picks_per_inch",
                                                   "warp_count",  "weft_count",   "fibre"};
    return names;
}

double parseYarnCount(const nlohmann::json& value, const std::string& key) {
    const std::string usage = ": need a number and a unit: \"20 tex\", \"200 dtex\", \"150 den\", \"30 Ne\" or \"50 Nm\"";
    if (!value.is_string()) throw std::invalid_argument(q(key) + " = " + value.dump() + usage);
    const std::string text = value.get<std::string>();
    double number = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (ec != std::errc()) throw std::invalid_argument(q(key) + " = \"" + text + "\"" + usage);
    std::string unit(end, text.data() + text.size());
    unit.erase(0, unit.find_first_not_of(' '));
    // ASTM D2260's conversions: denier is g per 9 km, Nm km per kg, Ne (cotton) 840 yd per lb.
    double tex = NAN;
    if (unit == "tex") tex = number;
    else if (unit == "dtex") tex = number / 10.0;
    else if (unit == "den") tex = number / 9.0;
    else if (unit == "Nm") tex = 1000.0 / number;
    else if (unit == "Ne") tex = 590.5 / number;
    else throw std::invalid_argument(q(key) + " = \"" + text + "\": '" + unit + "' is no yarn count unit" + usage);
    if (!(number > 0.0) || !(tex >= kMinTex && tex <= kMaxTex))
        throw std::invalid_argument(q(key) + " = \"" + text + "\": need a positive count between " + "0.01 and 10000 tex");
    return tex;
}

double yarnDiameterCm(double tex, double fibreDensity) {
    return std::sqrt(4.0 * tex * 1e-5 / (M_PI * kYarnPacking * fibreDensity));
}

double yarnTex(double diameterCm, double fibreDensity) {
    return M_PI * kYarnPacking * fibreDensity * diameterCm * diameterCm / (4.0 * 1e-5);
}

TextileKeys readTextileKeys(const nlohmann::json& j) {
    TextileKeys t;
    const std::optional<double> ends = threadsPerCm(j, "ends"), picks = threadsPerCm(j, "picks");
    const std::string endsKey = j.contains("ends_per_cm") ? "'ends_per_cm'" : "'ends_per_inch'",
                      picksKey = j.contains("picks_per_cm") ? "'picks_per_cm'" : "'picks_per_inch'";
    if (ends && !picks) throw std::invalid_argument(endsKey + " needs 'picks_per_cm' or 'picks_per_inch': a cloth has both");
    if (picks && !ends) throw std::invalid_argument(picksKey + " needs 'ends_per_cm' or 'ends_per_inch': a cloth has both");
    if (ends) {
        if (j.contains("repeat")) throw std::invalid_argument(endsKey + " and 'repeat' both set the repeat: give one");
        if (j.contains("scale")) throw std::invalid_argument(endsKey + " and 'scale' both set the repeat: give one");
        t.threadsPerCm = glm::dvec2(*ends, *picks);
    }
    for (const auto& [count, width, tex] : {std::tuple{"warp_count", "warp_width", &t.warpTex},
                                            std::tuple{"weft_count", "yarn_width", &t.weftTex}}) {
        if (!j.contains(count)) continue;
        if (j.contains(width))
            throw std::invalid_argument(q(count) + " and " + q(width) + " both set the yarn's width: give one");
        *tex = parseYarnCount(j[count], count);
    }
    t.fibreDensity = fibres().front().density;
    if (j.contains("fibre")) {
        const auto& all = fibres();
        const auto it = std::find_if(all.begin(), all.end(), [&](const Fibre& f) { return j["fibre"] == f.name; });
        if (it == all.end()) {
            std::string names;
            for (const Fibre& f : all) names += (names.empty() ? "" : ", ") + std::string(f.name);
            throw std::invalid_argument("'fibre' = " + j["fibre"].dump() + " is none of woven's fibres: " + names);
        }
        t.fibreDensity = it->density;
        t.fibre = it->name;
    }
    return t;
}

}  // namespace woven
