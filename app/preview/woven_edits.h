#pragma once
// The previewer's "make woven" and "revert": the scene as loaded plus an ordered list of edits,
// each a target (woven_assignment.h) and the woven parameters the panel tunes for it. The scene
// the window draws and renders is always the loaded one with the edits assigned, so the Render
// button, a saved scene file and `woven render` of that file agree. Free of GL and ImGui: the
// window and the tests drive it the same way.
#include <string>
#include <vector>

#include "scene_description.h"

namespace woven {

struct WovenEdit {
    std::string target;
    WovenParams params;
};

class WovenEdits {
public:
    explicit WovenEdits(SceneDescription loaded);

    const SceneDescription& scene() const { return scene_; }
    // Lights and the environment, which the window edits in place (materials come from edits).
    SceneDescription& sceneForLighting() { return scene_; }

    // The targets that name primitive `mesh`, least specific first: "*", its material's name
    // (when it has one), "mesh:NAME", then "node:NAME" for each node from the root down.
    std::vector<std::string> targetsFor(int mesh) const;

    // Makes `target` woven, starting from the parameters the first primitive it names shows now
    // (where it is not woven, the defaults with 2 mm weave elements on that primitive's UV
    // scale and its glTF base colour as the yarns'); an existing edit of `target` is kept. Returns the
    // edit's index. Throws SceneError for a target that names nothing.
    int makeWoven(const std::string& target);
    // Drops the edit of `target` (the loaded materials show again); false when there is none.
    bool revert(const std::string& target);

    const std::vector<WovenEdit>& edits() const { return edits_; }
    // Every edit at once (an undo), then apply().
    void restore(std::vector<WovenEdit> edits) { edits_ = std::move(edits); }
    // The panel's sliders: change the parameters, then apply().
    WovenParams& params(int edit) { return edits_.at(size_t(edit)).params; }
    // Rebuilds the scene's materials from the loaded ones and the edits; returns whether any
    // primitive's material index changed (the window then uploads the meshes again).
    bool apply();
    // The material (in scene()) of the first primitive `target` names, or -1.
    int materialOf(const std::string& target) const;
    // The primitives (indices into scene().meshes) `target` names.
    std::vector<size_t> meshesOf(const std::string& target) const;

private:
    // Whether `target` names primitive `mesh` by the names it was loaded with.
    bool names(const std::string& target, size_t mesh) const;

    SceneDescription scene_;
    std::vector<Material> loadedMaterials_;
    std::vector<int> loadedMeshMaterials_;
    std::vector<WovenEdit> edits_;
};

}  // namespace woven
