#include "cloth_simulation.h"

#include <cmath>

namespace drape {

ClothSimulation::ClothSimulation(const ClothSettings& settings, SignedDistance solid)
    : settings_(settings), solid_(std::move(solid)) {
    const int n = settings.resolution;
    const float spacing = settings.size / float(n - 1);
    const float c = std::cos(settings.yaw), s = std::sin(settings.yaw);
    position_.resize(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = i * spacing - settings.size / 2, z = j * spacing - settings.size / 2;
            position_[j * n + i] = settings.center + glm::vec3(c * x + s * z, 0.0f, -s * x + c * z);
        }
    previous_ = position_;
    const auto link = [&](int i0, int j0, int i1, int j1, float stiffness) {
        if (i1 < 0 || i1 >= n || j1 >= n) return;
        const int a = j0 * n + i0, b = j1 * n + i1;
        springs_.push_back({a, b, glm::length(position_[a] - position_[b]), stiffness});
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            link(i, j, i + 1, j, settings.structural);
            link(i, j, i, j + 1, settings.structural);
            link(i, j, i + 1, j + 1, settings.shear);
            link(i, j, i - 1, j + 1, settings.shear);
            link(i, j, i + 2, j, settings.bend);
            link(i, j, i, j + 2, settings.bend);
        }
}

void ClothSimulation::run() {
    for (int s = 0; s < settings_.steps; ++s) step();
}

void ClothSimulation::step() {
    const glm::vec3 gravity(0.0f, -9.81f, 0.0f);
    const float dt2 = settings_.timeStep * settings_.timeStep;
    for (size_t p = 0; p < position_.size(); ++p) {
        const glm::vec3 velocity = (position_[p] - previous_[p]) * settings_.damping;
        previous_[p] = position_[p];
        position_[p] += velocity + gravity * dt2;
    }
    for (int k = 0; k < settings_.iterations; ++k) {
        relaxSprings();
        collide();
    }
}

void ClothSimulation::relaxSprings() {
    for (const Spring& spring : springs_) {
        glm::vec3& a = position_[spring.a];
        glm::vec3& b = position_[spring.b];
        const glm::vec3 d = b - a;
        const float length = glm::length(d);
        if (length <= 0.0f) continue;
        const glm::vec3 correction = d * (0.5f * spring.stiffness * (length - spring.rest) / length);
        a += correction;
        b -= correction;
    }
}

void ClothSimulation::collide() {
    const float h = 1e-4f;  // central differences for the solid's normal
    for (size_t p = 0; p < position_.size(); ++p) {
        glm::vec3& x = position_[p];
        glm::vec3 normal(0.0f);
        float depth = 0.0f;
        const float d = solid_(x);
        if (d < settings_.thickness) {
            normal = glm::normalize(glm::vec3(solid_(x + glm::vec3(h, 0, 0)) - solid_(x - glm::vec3(h, 0, 0)),
                                              solid_(x + glm::vec3(0, h, 0)) - solid_(x - glm::vec3(0, h, 0)),
                                              solid_(x + glm::vec3(0, 0, h)) - solid_(x - glm::vec3(0, 0, h))));
            depth = settings_.thickness - d;
        } else if (x.y < settings_.thickness) {
            normal = glm::vec3(0.0f, 1.0f, 0.0f);
            depth = settings_.thickness - x.y;
        }
        if (depth <= 0.0f) continue;
        x += normal * depth;
        // Friction: keep only part of the tangential motion of this step, none into the solid.
        const glm::vec3 velocity = x - previous_[p];
        const glm::vec3 tangential = velocity - normal * glm::dot(velocity, normal);
        previous_[p] = x - tangential * (1.0f - settings_.friction);
    }
}

SignedDistance sphere(const glm::vec3& center, float radius) {
    return [=](const glm::vec3& p) { return glm::length(p - center) - radius; };
}

SignedDistance roundedBox(const glm::vec3& center, const glm::vec3& halfExtent, float radius) {
    return [=](const glm::vec3& p) {
        const glm::vec3 q = glm::abs(p - center) - (halfExtent - glm::vec3(radius));
        return glm::length(glm::max(q, glm::vec3(0.0f))) + std::fmin(std::fmax(q.x, std::fmax(q.y, q.z)), 0.0f) - radius;
    };
}

}  // namespace drape
