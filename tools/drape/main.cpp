// drape: simulates a square cloth falling onto an object and writes the scene as .glb.
// Deterministic: the same options give the same file. See tools/drape/README.md.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "cloth_simulation.h"
#include "drape_scene.h"

namespace {

// The cloth's woven material in the written file: a plain weave of red weft and golden warp,
// 80 weave elements per UV unit (about 6 pixels per element at 640 x 480 from the file's camera).
woven::WovenParams defaultCloth() {
    woven::WovenParams p;
    p.pattern = {1, 1, 1};
    p.repeat = {80.0f, 80.0f};
    p.ex = p.warp_ex = 100.0f;
    p.ey = p.warp_ey = 2.0f;
    p.cy = 0.5f;
    p.rs = 0.04f;
    p.weft_color = {0.55f, 0.12f, 0.10f};
    p.warp_color = {0.62f, 0.48f, 0.24f};
    p.noise = 0.1f;
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Drapes a cloth over an object by mass-spring simulation and writes the scene as .glb"};
    std::string out, layout = "studio", object = "sphere";
    drape::ClothSettings settings;
    app.add_option("--out,-o", out, "output .glb file")->required();
    app.add_option("--layout", layout, "studio (ground, large area light) or room (light reaches the cloth "
                                       "only after a bounce)")->check(CLI::IsMember({"studio", "room"}));
    app.add_option("--object", object, "what the cloth falls on")->check(CLI::IsMember({"sphere", "box"}));
    app.add_option("--resolution", settings.resolution, "cloth vertices per side")->check(CLI::Range(3, 256));
    app.add_option("--steps", settings.steps, "simulation steps of 5 ms")->check(CLI::Range(0, 100000));
    CLI11_PARSE(app, argc, argv);

    // Slightly turned and off-centre, so the folds are not perfectly symmetric.
    settings.yaw = 0.35f;
    drape::DrapeScene scene;
    drape::SignedDistance solid;
    if (object == "sphere") {
        const glm::vec3 center(0.0f, 0.5f, 0.0f);
        const float radius = 0.5f;
        settings.center = glm::vec3(0.05f, 1.05f, -0.03f);
        solid = drape::sphere(center, radius);
        // Drawn a little inside the collision surface, so the cloth never dips into it.
        scene.object = drape::sphereMesh(center, radius - 0.002f, 64, 32);
    } else {
        const glm::vec3 center(0.0f, 0.35f, 0.0f), half(0.42f, 0.35f, 0.42f);
        const float radius = 0.08f;
        settings.center = glm::vec3(0.05f, 0.75f, -0.03f);
        solid = drape::roundedBox(center, half, radius);
        scene.object = drape::roundedBoxMesh(center, half - glm::vec3(0.002f), radius - 0.002f, 12);
    }
    drape::ClothSimulation cloth(settings, solid);
    const auto start = std::chrono::steady_clock::now();
    cloth.run();
    std::cerr << "simulated " << settings.steps << " steps in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    scene.cloth = drape::clothMesh(cloth);
    scene.clothMaterial = defaultCloth();
    scene.layout = layout == "room" ? drape::Layout::Room : drape::Layout::Studio;
    try {
        drape::writeDrapeScene(scene, out);
    } catch (const std::exception& e) {
        std::cerr << "drape: " << e.what() << "\n";
        return 1;
    }
    std::cerr << "wrote " << out << ": cloth of " << scene.cloth.indices.size() / 3 << " triangles\n";
    return 0;
}
