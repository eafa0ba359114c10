#pragma once
// The library of named fabrics (assets/fabrics, docs/FABRICS.md): one JSON file a fabric,
//   {"name": "denim", "title": "...", "source": "...", "note": "...", "material": {...}}
// whose "material" is a woven material with textile keys (textile_units.h). A material names
// one by "preset": NAME and overrides any of its keys (withPreset()).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace woven {

struct Fabric {
    std::string name, title, source, note;
    std::string file;         // the file it was read from
    nlohmann::json material;  // its "wif", if any, as a path the working directory resolves
};

// $WOVEN_FABRIC_DIR, else the source tree's assets/fabrics.
std::string fabricDirectory();
// The library's fabrics by name. Throws std::invalid_argument naming the file for one that cannot
// be read or lacks a key (its material is checked by materialFromJson()).
std::vector<std::string> fabricNames();
Fabric readFabric(const std::string& name);  // an unknown name: the message lists the library

// The fabric `material["preset"]` names, with the other keys of `material` over it: a key
// replaces the fabric's keys that set the same thing (`repeat` its thread counts, `yarn_width`
// its weft count, `pattern` its tile or draft, docs/FABRICS.md). Throws for a "preset" that
// is not a fabric's name.
nlohmann::json withPreset(const nlohmann::json& material, Fabric& fabric);

}  // namespace woven
