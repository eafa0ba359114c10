#pragma once
// The textile keys of a woven material (docs/FABRICS.md): thread counts as a weaver gives them
// (ends and picks per cm or per inch) and yarn counts with their unit ("20 tex", "150 den",
// "30 Ne", "50 Nm"), and the yarn diameter a count and a fibre make, which sets the model's yarn
// widths. Read by materialFromJson(); the mesh turns the thread counts into `repeat`.
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace woven {

constexpr double kCmPerInch = 2.54;
// The fraction of a yarn's circular cross-section that is fibre, a typical value for spun yarns
// (Hearle, Grosberg and Backer, Structural Mechanics of Fibers, Yarns, and Fabrics, 1969).
constexpr double kYarnPacking = 0.6;

// A fibre and its density in g/cm^3 (Morton and Hearle, Physical Properties of Textile Fibres).
struct Fibre {
    const char* name;
    double density;
};
const std::vector<Fibre>& fibres();  // cotton first: the default

// What a material's textile keys say; a side without a count has no tex.
struct TextileKeys {
    std::optional<glm::dvec2> threadsPerCm;  // ends (across u), picks (across v)
    std::optional<double> warpTex, weftTex;  // linear density in tex (g per km)
    double fibreDensity = 0.0;               // g/cm^3, of "fibre" or cotton
    std::string fibre;                       // "fibre" as given; empty when not given
};

// Throws std::invalid_argument naming the key: a count that is not positive and finite, a unit
// woven does not know, a side given twice (per cm and per inch), ends without picks, thread
// counts beside 'repeat' or "scale", a yarn count beside the width it sets.
TextileKeys readTextileKeys(const nlohmann::json& j);
// The keys readTextileKeys() reads, which the model's JSON does not take.
const std::vector<const char*>& textileKeyNames();

// "20 tex", "200 dtex", "150 den", "30 Ne", "50 Nm" in tex; throws naming `key`.
double parseYarnCount(const nlohmann::json& value, const std::string& key);

// A yarn's diameter in cm from its count and fibre: d = sqrt(4 T / (pi phi rho)) with T in g/cm
// (tex x 1e-5), phi = kYarnPacking and rho in g/cm^3; and the count back from a diameter.
double yarnDiameterCm(double tex, double fibreDensity);
double yarnTex(double diameterCm, double fibreDensity);

}  // namespace woven
