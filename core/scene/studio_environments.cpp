#include "studio_environments.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "environment_mapping.h"
#include "scene_lighting.h"

namespace woven {

namespace {

// An equirectangular image of 512 x 256 whose pixels are `radiance` of their directions.
template <typename F>
Environment generated(F radiance) {
    auto image = std::make_shared<Image>();
    image->width = 512;
    image->height = 256;
    image->pixels.resize(size_t(image->width) * image->height);
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x)
            image->at(x, y) = glm::vec3(radiance(equirectDirection({(x + 0.5f) / image->width, (y + 0.5f) / image->height})));
    Environment env;
    env.color = glm::vec3(1.0f);
    env.image = std::move(image);
    return env;
}

// `below` under the horizon and `above` over it, blended across a band of about 3 degrees.
float horizon(const glm::vec3& d, float below, float above) {
    const float t = std::clamp(d.y / 0.05f * 0.5f + 0.5f, 0.0f, 1.0f);
    return below + (above - below) * t;
}

// One large soft box above the front, in a dark studio: a product shot's key light alone.
Environment softBox() {
    const SoftBox box{{0.0f, 0.8f, 0.6f}, 0.55f, 0.35f, 0.12f, 6.0f};
    return generated([&](const glm::vec3& d) { return horizon(d, 0.02f, 0.05f) + box.at(d); });
}

// A tall window on the left of a dim room: light from one side, the other side in shade.
Environment window() {
    const SoftBox pane{{-1.0f, 0.2f, 0.25f}, 0.3f, 0.45f, 0.03f, 8.0f};
    return generated([&](const glm::vec3& d) { return horizon(d, 0.04f, 0.08f) + pane.at(d); });
}

// The CIE standard overcast sky, radiance (1 + 2 cos theta) / 3 of the zenith's, over a grey
// ground: soft light from above, no direction to it.
Environment overcast() {
    constexpr float kZenith = 1.2f, kGround = 0.15f;
    return generated([](const glm::vec3& d) { return horizon(d, kGround, kZenith * (1.0f + 2.0f * std::max(d.y, 0.0f)) / 3.0f); });
}

}  // namespace

float SoftBox::at(const glm::vec3& d) const {
    const glm::vec3 c = glm::normalize(centre);
    const glm::vec3 right = glm::normalize(glm::cross(c, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, c);
    const float forward = glm::dot(d, c);
    if (forward <= 0.0f) return 0.0f;
    const float x = std::atan2(glm::dot(d, right), forward), y = std::atan2(glm::dot(d, up), forward);
    const auto edge = [&](float a, float half) { return std::clamp((half - std::abs(a)) / soft + 0.5f, 0.0f, 1.0f); };
    return radiance * edge(x, halfWidth) * edge(y, halfHeight);
}

const std::vector<StudioEnvironment>& studioEnvironments() {
    static const std::vector<StudioEnvironment> table = {
        {"studio", "three soft boxes: a key front left, a fill right, a rim behind (the default light)", studioEnvironment},
        {"softbox", "one large soft box above the front, in a dark studio", softBox},
        {"window", "a tall window on the left of a dim room", window},
        {"overcast", "an overcast sky over a grey ground", overcast},
    };
    return table;
}

const StudioEnvironment* findStudioEnvironment(const std::string& name) {
    for (const StudioEnvironment& s : studioEnvironments())
        if (name == s.name) return &s;
    return nullptr;
}

std::string studioEnvironmentNames() {
    std::string names;
    const auto& table = studioEnvironments();
    for (size_t i = 0; i < table.size(); ++i)
        names += std::string(i == 0 ? "" : i + 1 == table.size() ? " or " : ", ") + table[i].name;
    return names;
}

}  // namespace woven
