#pragma once
// The material being tuned, saved into a woven scene file (docs/SCENE_FORMAT.md) and read back,
// through core's paramsToJson and materialFromJson, with or beside its draft. Errors throw
// std::runtime_error naming the file.
#include <optional>
#include <string>
#include <vector>

#include "draft_editor.h"
#include "material_json.h"
#include "scene_camera.h"
#include "scene_description.h"

namespace woven {

// Sets materials.<materialName> of the scene file at `path` to `params`, keeping everything else
// in it. A file that does not exist yet becomes a scene file naming `gltf` (as given); with no
// glTF (the procedural cloth) it becomes the bare parameter object. Written atomically.
void saveMaterial(const std::string& path, const std::string& materialName, const WovenParams& params,
                  const std::string& gltf);

// What the window's Save writes into a woven scene file: what a render of that file needs to be
// the Render button's frame.
struct SceneSave {
    std::vector<std::pair<std::string, WovenParams>> materials;  // every edit: target, parameters
    std::optional<CameraView> camera;  // the view, where it was moved from the scene's camera
    RenderHints render;                // the Render button's settings
    std::optional<glm::vec3> environmentColor;  // where the window changed it
    // The files the scene was read from (scene file, glTF, buffers, images, drafts): never saved over.
    std::vector<std::string> inputs;
    // Save As: the file starts anew as the opened scene, replacing the woven scene file there
    // rather than keeping what it had (which may name another glTF).
    bool startAnew = false;
};

// `save` into the woven scene file at `path`. An existing scene file keeps everything else it
// has (saved again, it is overwritten the same way); a new one starts as the scene the window
// opened (`scenePath`): a copy of that scene file, its relative paths rebased to `path`'s folder,
// or a scene file naming that glTF. The procedural cloth (no `scenePath`) saves its one material
// as a bare parameter object. Refused: a path that is one of `save.inputs`, that does not end in
// .json, or whose file is not a woven scene file.
void saveScene(const std::string& path, const std::string& scenePath, const SceneSave& save);

// The glTF file a scene path stands for: itself, or the one a woven scene file (.json) names,
// resolved against its folder; empty for none (the procedural cloth).
std::string sceneGltf(const std::string& scenePath);

// The same with the draft the material was made from: the draft is written (and renamed) as a
// WIF file beside `path` (its name with .wif), and the material names it ("wif") instead of
// holding what the draft sets (fieldsSetByDraft()). Returns the WIF file's path.
std::string saveMaterialWithDraft(const std::string& path, const std::string& materialName, const WovenParams& params,
                                  const std::string& gltf, DraftEditor& draft);

// From a scene file (its materials."*", then materials.<materialName>, on top of `base`) or a
// bare parameter object; a "wif" there is read relative to the file. Draft warnings go to
// `warnings`.
MaterialJson loadMaterial(const std::string& path, const std::string& materialName, const WovenParams& base,
                          std::vector<std::string>& warnings);

}  // namespace woven
