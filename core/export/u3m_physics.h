#pragma once
// U3M 1.1's `physics` section of a woven material (docs/EXPORT.md): what a fashion tool drapes the
// cloth by, from what woven knows of it.
//   weight        g/m2, FabricMeasures' figure (the one `woven fabrics` prints)
//   thickness     mm, the warp's and the weft's yarn diameters together: where they cross, one
//                 lies over the other (Peirce's model of a cloth's section)
//   composition   the yarns' fibre ("fibre"), all of it; null where the material names none
//   material_type Woven
//   construction  from the weave (weave_construction.h)
#include <nlohmann/json.hpp>

#include "fabric_measures.h"
#include "textile_units.h"
#include "woven_params.h"

namespace woven {

// `textile`: the yarn counts and fibre the material gave (its thread counts are in `measures`).
nlohmann::json u3mPhysics(const WovenParams& params, const FabricMeasures& measures, const TextileKeys& textile);

// The thickness (mm) u3mPhysics() writes.
double clothThicknessMm(const WovenParams& params, const FabricMeasures& measures, const TextileKeys& textile);

}  // namespace woven
