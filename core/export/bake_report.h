#pragma once
// How close a bake is to the woven model, measured with woven's own renderer (`woven export
// --report`, docs/EXPORT.md): a flat cloth of the material under the same light (a sun near the
// mirror direction of the view, so the yarns' highlights show, and a uniform sky seen through the
// gaps) and the same camera (45 degrees above the cloth), rendered near (a few threads across the
// frame) and far (many threads a pixel) with the model and with the bake, and the relative RMSE
// between them, sqrt(sum (bake - model)^2 / sum model^2) over pixels and channels, with the
// renders' noise taken out: the bake and the model are rendered with different seeds, so the
// squared error is the bias's plus the noise of two renders, and the model against itself with a
// third seed measures that noise, which is subtracted (and shown). Per feature: the same with one
// part of the bake taken away (anisotropy, the normal map's bump, the gaps' alpha, the sheen).
#include <string>
#include <vector>

#include "scene_description.h"
#include "woven_bake.h"

namespace woven {

// The far view is rendered at a quarter of the width and height with 16 times the samples: the
// same cost, and a quarter of the noise, which the sub-pixel sparkle of the yarns' highlights
// makes large there.
struct ReportOptions {
    int width = 128, height = 96;  // of the near view
    int spp = 256;                 // of the near view
    uint64_t seed = 1;
    int threads = 0;              // 0: all cores
    double nearThreads = 12.0;    // threads across the near frame
    double farThreads = 1200.0;   // and across the far one
    std::string imageFolder;      // when not empty: PNGs of the model and the bake, near and far,
    std::string imagePrefix;      // named PREFIX_MATERIAL_near_model.png ...
};

struct ReportRow {
    std::string what;  // "bake", "without anisotropy", ...
    double nearError = 0.0, farError = 0.0;
};

// The far field (far_field.h: relative RMSE against the model's) of the bake's level 0 and of its
// coarsest mip level, fitted in the model as the bake does it and box-filtered in texel space as
// a viewer makes it from level 0.
struct MipComparison {
    double level0 = 0.0, coarsestFitted = 0.0, coarsestBoxFiltered = 0.0;
};
MipComparison compareMipLevels(const WovenParams& params, const BakedMaterial& baked);

struct BakeReport {
    std::string material;
    std::vector<ReportRow> rows;  // the bake first, then one per feature taken away (noise removed), the noise last
    MipComparison farField;
    std::vector<std::string> images;  // the PNGs written
};

// `wovenMaterial`: the scene's woven material that `baked` was made from.
BakeReport reportBake(const Material& wovenMaterial, const BakedMaterial& baked, const ReportOptions& options);

// The report as a table, a few lines.
std::string formatReport(const BakeReport& report, const ReportOptions& options);

}  // namespace woven
