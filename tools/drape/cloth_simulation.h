#pragma once
// A square cloth as a mass-spring system: a grid of particles joined by structural, shear and
// bend springs, moved by gravity under Verlet integration with damping, the springs enforced
// by Gauss-Seidel relaxation (Jakobsen 2001), colliding with the ground plane y = 0 and one
// solid given by its signed distance. Single-threaded and free of randomness: the same
// settings give the same cloth, bit for bit, with the same build.
#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace drape {

struct ClothSettings {
    int resolution = 88;                    // vertices per side
    float size = 1.6f;                      // side length, metres
    glm::vec3 center{0.0f, 1.05f, 0.0f};    // of the flat cloth at rest
    float yaw = 0.0f;                       // rotation of the grid about +y, radians
    float timeStep = 1.0f / 200.0f;         // seconds
    int steps = 1000;
    int iterations = 20;                    // relaxation passes per step
    float damping = 0.985f;                 // velocity kept per step
    float structural = 1.0f, shear = 0.9f, bend = 0.25f;  // fraction of a spring's error fixed per pass
    float thickness = 0.006f;               // kept between the cloth and the solids, metres
    float friction = 0.6f;                  // tangential velocity removed on contact
};

// Signed distance to a solid: negative inside.
using SignedDistance = std::function<float(const glm::vec3&)>;

class ClothSimulation {
public:
    ClothSimulation(const ClothSettings& settings, SignedDistance solid);

    void run();  // settings.steps steps

    int resolution() const { return settings_.resolution; }
    // Particle (i, j) is at index j * resolution + i; i runs along u, j along v.
    const std::vector<glm::vec3>& positions() const { return position_; }

private:
    struct Spring {
        int a, b;
        float rest, stiffness;
    };
    void step();
    void relaxSprings();
    void collide();

    ClothSettings settings_;
    SignedDistance solid_;
    std::vector<glm::vec3> position_, previous_;
    std::vector<Spring> springs_;
};

// Signed distances of the solids the cloth can drape over.
SignedDistance sphere(const glm::vec3& center, float radius);
SignedDistance roundedBox(const glm::vec3& center, const glm::vec3& halfExtent, float radius);

}  // namespace drape
