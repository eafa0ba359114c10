#pragma once
// The panel's Render section: the final frame's settings, the Render button (core's RenderJob for
// the window's camera on a background thread: final_render.h), Export, the progress and saving
// the frame; and the frame itself, shown in the view in place of the preview until the view or
// the cloth changes, and while the preview shows, an outline of what it will hold.
#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "display_transform.h"
#include "final_render.h"
#include "status_line.h"

namespace woven {

class RenderSection {
public:
    // A scene opened: any render cancelled, no frame, these settings (the Render button's, but
    // for the camera) and these default files for Save PNG/EXR and Export.
    void reset(const RenderSettings& settings, const std::string& imagePath, const std::string& exportPath);

    // What the section renders and exports: the scene as the window shows it, the camera the
    // frame renders through and the view's own, and the edited material (a U3M's; empty: the first).
    struct Shown {
        const SceneDescription& scene;
        Camera renderCamera, viewCamera;
        std::string material;
        bool denoise = true;
    };
    void draw(const Shown& shown, const DisplayTransform& display, StatusLine& status);
    // Once a frame, before the panel: the job's latest pass, if new, into the frame's texture.
    void poll(const DisplayTransform& display);
    // The display transform changed: the frame's texture again.
    void redisplay(const DisplayTransform& display);
    // Behind the panel: the frame letterboxed in the view while shown, else the outline of what it
    // will hold (the render shares the view's camera and vertical field).
    void drawInView() const;

    void hide() { show_ = false; }  // the frame is of an old view or cloth
    bool shown() const { return show_ && image_.has_value(); }
    bool running() const { return job_.running(); }
    void cancel() { job_.cancel(); }
    const RenderSettings& settings() const { return settings_; }
    // For the widget map: the settings, and the job and its frame.
    nlohmann::json settingsState() const;
    nlohmann::json frameState() const;
    // The frame's texture goes while the window's GL context is current.
    void releaseTexture();

private:
    void exportShown(const Shown& shown, StatusLine& status);

    FinalRender job_;
    std::optional<FilmImage> image_;  // the job's latest pass
    GLuint texture_ = 0;              // made with the first frame
    bool show_ = false;               // the frame in place of the preview
    bool done_ = false;  // the job ended (not cancelled, not failed) and its last pass is image_
    RenderSettings settings_;
    char imagePath_[512] = "render.png";
    char exportPath_[512] = "scene.glb";
};

}  // namespace woven
