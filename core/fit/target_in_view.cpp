#include "target_in_view.h"

#include <cstdio>

namespace woven {

namespace {

// The share of the frame's pixels where `a` is brighter than `b` in some channel. Both renders
// take the same random numbers at each pixel, so a pixel that does not see the target is the
// same in both, to the bit.
double brighterShare(const Image& a, const Image& b) {
    size_t brighter = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        if (glm::any(glm::greaterThan(a.pixels[i], b.pixels[i]))) ++brighter;
    return a.pixels.empty() ? 0.0 : double(brighter) / double(a.pixels.size());
}

void makeBlack(Material& m) {
    Material black;
    black.name = m.name;
    black.doubleSided = m.doubleSided;
    black.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    black.specular = 0.0f;
    black.roughness = 1.0f;
    m = black;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", 100.0 * share);
    return text;
}

}  // namespace

void checkTargetSeenAndLit(const Shot& shot, FitRenderSettings settings, const std::atomic<bool>& cancel) {
    settings.spp = 1;
    settings.deadline = std::chrono::steady_clock::time_point::max();
    const Image dark = renderShotWith(shot, makeBlack, settings, cancel);
    WovenParams grey = shot.scene->materials[size_t(shot.materials.at(0))].woven.value_or(WovenParams{});
    grey.tile.clear();
    grey.warp_colors.clear();
    grey.weft_colors.clear();
    grey.weft_color = grey.warp_color = glm::vec3(0.5f);
    grey.transmission = 1.0f;
    const Image lit = renderShot(shot, grey, settings, cancel);
    if (cancel.load() || brighterShare(lit, dark) >= kLeastTargetShare) return;
    // White and unlit (KHR_materials_unlit): seen by the camera, and lighting nothing else.
    const Image shown = renderShotWith(
        shot,
        [](Material& m) {
            makeBlack(m);
            m.doubleSided = true;
            m.baseColor = glm::vec4(1.0f);
            m.unlit = true;
        },
        settings, cancel);
    if (cancel.load()) return;
    const double seen = brighterShare(shown, dark);
    if (seen < kLeastTargetShare)
        throw FitError(shot.path + ": the camera sees the target in " + percent(seen) +
                       " of the frame: something in the scene hides it (a shot's frame shows the swatch)");
    throw FitError(shot.path + ": no light of the shot reaches the target where the camera sees it (lit in " +
                   percent(brighterShare(lit, dark)) + " of the frame): a light of intensity 0, or one hidden from the swatch");
}

}  // namespace woven
