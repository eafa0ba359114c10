#pragma once
// `woven share SCENE -o PAGE/`: a folder that shows the cloth to someone without a renderer
// (docs/EXPORT.md): index.html with Google's <model-viewer> (copied in from npm, so the page works
// offline and from a file:// URL), the scene's export as scene.glb (also inside the page, as a
// data URI: a page opened from disk may not fetch files beside it), woven's final render as the
// poster, the studio environment woven lights scenes with (scene_lighting.h) as the viewer's
// light, the camera on the cloth (the scene's own, else the woven meshes' bounds, so a floor or a
// room does not shrink the cloth), camera controls and auto-rotation, and each woven material's
// name, thread counts, weight and construction.
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_description.h"
#include "scene_export.h"

namespace woven {

struct ShareError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// model-viewer-umd.min.js from npm's @google/model-viewer: $WOVEN_MODEL_VIEWER, else where
// tools/install-deps.sh --share installs it (found when woven was built).
std::string defaultModelViewer();

struct ShareOptions {
    ExportOptions exportOptions;
    std::string modelViewer = defaultModelViewer();  // model-viewer-umd.min.js from @google/model-viewer's dist/
    int posterSize = 640;     // pixels along the poster's longer side
    int posterSpp = 64;
};

// Writes the folder (created if missing; its parent must exist), index.html last. Returns the
// export's warnings. Throws ShareError naming the folder or the file (no model-viewer, nothing
// woven, a folder that cannot be written).
std::vector<std::string> writeSharePage(const SceneDescription& scene, const std::string& folder, const ShareOptions& options);

}  // namespace woven
