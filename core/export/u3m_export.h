#pragma once
// `woven export SCENE -o FABRIC.u3ma` (or FABRIC.u3m): one woven material of a scene as a Unified
// 3D Material, U3M 1.1 (github.com/vizoogmbh/u3m, docs/EXPORT.md), what fashion tools (VStitcher,
// Vizoo, Style3D, Blender's add-on) exchange fabrics as:
//   front, back  the material baked as `woven export` bakes glTF (core/bake), the back from the
//                weave's other face (warp and weft floats swapped); each map a whole number of
//                weave repeats wide and high, in millimetres at the cloth's real thread count
//   physics      u3m_physics.h: weight, thickness, composition, Woven, construction
//   preview      the scene rendered by woven, small
//   custom       "woven": the material's parameters with its thread counts, so that woven reads
//                its own file back as the same cloth (u3m_material.h)
// .u3ma: one archive (u3ma_archive.h) with NAME.u3m at its root and NAME_textures/ beside it;
// .u3m: the same files written into the .u3m's folder, the .u3m last.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabric_measures.h"
#include "scene_description.h"
#include "woven_bake.h"

namespace woven {

struct U3mError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct U3mOptions {
    BakeOptions bake;
    std::string material;  // the woven material's name; empty: the scene's only one
    int previewSize = 256;  // pixels along the preview's longer side; 0: no preview
    int previewSpp = 16;
};

struct U3mExport {
    std::string material;       // its name
    nlohmann::json document;    // the .u3m's JSON
    FabricMeasures measures;    // at its real thread count
    glm::dvec2 mapMm{0.0};      // each map's width and height in mm
    std::vector<std::string> notes;  // what U3M cannot say and the export approximated
};

// What the material's woven layers said of the real cloth (Material::textile); else no counts,
// no fibre named, and cotton's density, as measureFabric() takes them.
TextileKeys textileOf(const Material& m);

// The woven material's measures (fabric_measures.h) at its real thread count: as its material
// gave it (thread counts, "scale": "draft", a preset), else its `repeat` on the meshes that use
// it. Throws U3mError for a material on no mesh with texture coordinates.
FabricMeasures measureSceneMaterial(const SceneDescription& scene, int material);

// The woven parameters of the cloth's other face: the weave's top yarn swapped in every cell.
WovenParams backFace(const WovenParams& front);

// Bakes and writes, with a new UUID4 and the time now. Throws
// U3mError naming the scene or the file (no woven material, several without
// options.material, no real size, a path not ending in .u3m or .u3ma or not writable: checked
// before baking); nothing is left looking finished then.
U3mExport exportU3m(const SceneDescription& scene, const std::string& path, const U3mOptions& options);

}  // namespace woven
