// `woven fabrics`: the library of named fabrics (assets/fabrics, docs/FABRICS.md) with what a
// weaver quotes of each: thread counts, yarn counts, weight, cover and the size of one repeat.
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "fabric_library.h"
#include "fabric_measures.h"
#include "material_json.h"

namespace woven {

namespace {

struct Entry {
    Fabric fabric;
    FabricMeasures measures;
};

// Each fabric read through "preset", as a scene's material takes it.
std::vector<Entry> readLibrary() {
    std::vector<Entry> entries;
    for (const std::string& name : fabricNames()) {
        std::vector<std::string> warnings;
        const MaterialJson read = materialFromJson({{"preset", name}}, WovenParams{}, "", warnings);
        for (const std::string& w : warnings) std::cerr << "warning: " << read.preset << ": " << w << "\n";
        Entry e{readFabric(name), {}};
        const std::optional<FabricMeasures> m = measureMaterial(read);
        if (!m) throw std::invalid_argument(e.fabric.file + ": a library fabric gives 'ends_per_cm' and 'picks_per_cm' (or per inch)");
        e.measures = *m;
        entries.push_back(std::move(e));
    }
    return entries;
}

nlohmann::json toJson(const Entry& e) {
    const FabricMeasures& m = e.measures;
    const nlohmann::json& material = e.fabric.material;
    nlohmann::json j = {
        {"name", e.fabric.name},
        {"title", e.fabric.title},
        {"ends_per_cm", m.threadsPerCm.x},
        {"picks_per_cm", m.threadsPerCm.y},
        {"ends_per_inch", m.threadsPerCm.x * kCmPerInch},
        {"picks_per_inch", m.threadsPerCm.y * kCmPerInch},
        {"weight_g_per_m2", m.gramsPerSquareMetre},
        {"cover", {{"warp", m.cover.x}, {"weft", m.cover.y}, {"cloth", m.clothCover}}},
        {"repeat_threads", {m.repeatThreads.x, m.repeatThreads.y}},
        {"repeat_cm", {m.repeatCm.x, m.repeatCm.y}},
        {"source", e.fabric.source},
        {"file", e.fabric.file},
    };
    for (const char* key : {"warp_count", "weft_count", "fibre"})
        if (material.contains(key)) j[key] = material[key];
    if (!e.fabric.note.empty()) j["note"] = e.fabric.note;
    return j;
}

}  // namespace

void addFabricsCommand(CLI::App& app) {
    auto json = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand("fabrics", "List the library of named fabrics that a material's \"preset\" names");
    cmd->add_flag("--json", *json, "one JSON array: each fabric's name, thread counts, yarn counts, weight, cover, repeat and source");
    cmd->callback([json] {
        const std::vector<Entry> entries = readLibrary();
        if (*json) {
            nlohmann::json all = nlohmann::json::array();
            for (const Entry& e : entries) all.push_back(toJson(e));
            std::cout << all.dump(2) << "\n";
            return;
        }
        std::printf("%-20s %-13s %-19s %7s %5s %-15s %s\n", "name", "threads/cm", "yarn counts", "g/m2", "cover",
                    "repeat cm", "title");
        for (const Entry& e : entries) {
            const FabricMeasures& m = e.measures;
            const nlohmann::json& material = e.fabric.material;
            const auto count = [&](const char* key) {
                return material.contains(key) ? material[key].get<std::string>() : std::string("-");
            };
            char threads[32], counts[64], repeat[32];
            std::snprintf(threads, sizeof threads, "%.4g x %.4g", m.threadsPerCm.x, m.threadsPerCm.y);
            std::snprintf(counts, sizeof counts, "%s / %s", count("warp_count").c_str(), count("weft_count").c_str());
            std::snprintf(repeat, sizeof repeat, "%.3g x %.3g", m.repeatCm.x, m.repeatCm.y);
            std::printf("%-20s %-13s %-19s %7.0f %5.2f %-15s %s\n", e.fabric.name.c_str(), threads, counts,
                        m.gramsPerSquareMetre, m.clothCover, repeat, e.fabric.title.c_str());
            std::printf("%-20s source: %s\n", "", e.fabric.source.c_str());
        }
    });
}

}  // namespace woven
