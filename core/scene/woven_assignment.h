#pragma once
// Making parts of a scene woven without editing its glTF file: scene files' "materials", the
// command line's --woven TARGET=JSON and the previewer's "make woven" all name the parts by a
// target (docs/SCENE_FORMAT.md):
//   "NAME" or "material:NAME"   the primitives whose material is NAME
//   "mesh:NAME"                 the primitives of glTF mesh NAME
//   "node:NAME"                 the primitives of node NAME and of every node below it
//   "*"                         every primitive, those without a material included
// NAME may be a glob (*, ? and [...], as a shell matches file names; a backslash makes the next
// character literal).
// Each primitive takes the woven parameters of every target that names it, layered from the
// least specific to the most: "*", material globs, material names, mesh globs, mesh names,
// then node targets by the depth of the node they match, a deeper node over a shallower one
// and a name over a glob at the same depth; targets equally specific apply in the order given.
// The layers go on top of what its material already has (its WOVEN_fabric, else the defaults).
// A material shared by primitives that end up with different parameters is split: each group
// gets a copy (textures, emission and sides kept) named "MATERIAL [target]", so making one mesh
// woven never changes another that shared its glTF material.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

struct WovenAssignment {
    std::string target;
    nlohmann::json params;  // a woven material's JSON (material_json.h, "wif" and "scale" included), a layer
    std::string where;      // for messages: "materials.Cloth", "--woven Cloth"
    std::string directory;  // where a "wif" path is relative to (the scene file's folder)
};

// Throws SceneError "<scene.source>: <where>: <problem>" for a target that matches nothing
// (listing the scene's materials, meshes and nodes) or parameters that are invalid (a draft
// that cannot be read included). "scale": "draft" and thread counts (ends_per_cm, ...) measure
// each group of primitives they make. What a draft's reader approximated, jammed yarn counts and
// UVs too uneven for one physical scale go to scene.warnings and stderr, once per line.
void assignWoven(SceneDescription& scene, const std::vector<WovenAssignment>& assignments);

// The command line's "TARGET=JSON" ("wif" paths relative to the working directory). Throws
// SceneError naming scene.source and the option.
WovenAssignment parseWovenOption(const SceneDescription& scene, const std::string& option);

// "the scene has materials 'A', 'B'; meshes ...; nodes ... (targets: ...)": for errors.
std::string whatTargetsCanName(const SceneDescription& scene);

// The target that names exactly the material, mesh or node called `name`, whatever characters
// the name holds (wildcards escaped, a material name that looks like a prefix prefixed).
enum class TargetKind { Material, Mesh, Node };
std::string literalTarget(TargetKind kind, const std::string& name);

// Whether `target` names primitive `mesh`, whose material is `material` (null: it has none).
bool targetNames(const std::string& target, const Mesh& mesh, const Material* material);

}  // namespace woven
