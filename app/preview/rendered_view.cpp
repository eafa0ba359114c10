// The window's side of the Rendered mode (rendered_viewport.h): the toggle and its key, what the
// view hands the path tracer each frame, the frame it draws, and what the status line and the
// widget map say of it.
#include <imgui.h>

#include "image_texture.h"
#include "preview_window_impl.h"
#include "view_area.h"

namespace woven {

void PreviewWindow::setRenderedView(bool on) {
    renderedView_ = on;
    if (!on) rendered_.stop();
    renderedImage_.reset();
}

// R switches between the Rendered and the GLSL view, unless a text field takes the key.
void PreviewWindow::handleViewKeys() {
    if (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(GLFW_KEY_R, false)) setRenderedView(!renderedView_);
}

// While the path tracer refines a still view, or renders the Render button's frame, the window
// draws at most kRefreshSeconds apart (sooner on an input): the cores are the path tracer's.
// Returns whether it waited.
bool PreviewWindow::restWhileRendering() {
    constexpr double kRefreshSeconds = 0.1;
    const bool tracing = (renderedView_ && rendered_.running()) || render_.running();
    if (!tracing || interacting_ || inputs_ != inputsSeen_) return false;
    glfwWaitEventsTimeout(kRefreshSeconds);
    return true;
}

// The view's frame in Rendered mode: what the window shows now (scene, camera, the Render
// button's size, sampler and seed) handed to the path tracer, which starts again where it changed,
// and its latest image letterboxed in the view as the Render button's frame is.
void PreviewWindow::drawRenderedView() {
    RenderSettings settings = viewportSettings(render_.settings());
    settings.camera = camera_.camera();
    rendered_.show(scene(), settings, interacting_, options_.frame.denoise);
    std::optional<Image> image = rendered_.newImage();
    if (image) renderedImage_ = std::move(image);
    // A new image, or the exposure or tone curve changed.
    const bool displayChanged = display_.exposure != renderedDisplay_.exposure || display_.toneMap != renderedDisplay_.toneMap;
    if (renderedImage_ && (image || displayChanged)) {
        uploadImageTexture(renderedTexture_, *renderedImage_, display_);
        renderedDisplay_ = display_;
    }
    if (renderedImage_) drawInView(renderedTexture_, float(renderedImage_->width) / float(renderedImage_->height));
}

// For the widget map: the progress, and the mean colour of the image drawn, by which a test sees
// the view change.
nlohmann::json PreviewWindow::renderedViewState() const {
    const ViewportProgress p = rendered_.progress();
    nlohmann::json mean = nullptr;
    if (renderedImage_ && !renderedImage_->pixels.empty()) {
        const glm::dvec3 m = meanColour(*renderedImage_);
        mean = {m.r, m.g, m.b};
    }
    return {{"on", renderedView_},
            {"samples", p.samples},
            {"target", p.target},
            {"denoised_at", p.denoisedAt},
            {"size", {p.width, p.height}},
            {"seconds", p.seconds},
            {"converged", p.converged},
            {"restarts", p.restarts},
            {"status", renderedView_ ? rendered_.statusText() : ""},
            {"image", renderedImage_ ? nlohmann::json{renderedImage_->width, renderedImage_->height} : nlohmann::json(nullptr)},
            {"mean", mean},
            {"error", rendered_.error()}};
}

}  // namespace woven
