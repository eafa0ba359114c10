// What opening a scene costs the preview's ambient, per shipped scene as `woven preview` opens it:
// the sky's share per vertex (sky_visibility.h, traced once per mesh upload) and the bounced
// light (bounced_light.h, traced again after a light edit), their rays and seconds; and what a
// woven edit costs instead (wovenAlbedos() of the scene's first woven material). A printed table,
// never a test: every figure depends on the machine and its load. CPU seconds beside the wall's:
// the bounce runs on every core (TBB), the sky on one.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "bounced_light.h"
#include "frame_options.h"
#include "scene_loader.h"
#include "sky_visibility.h"

namespace woven {
namespace {

using Clock = std::chrono::steady_clock;

// Wall and CPU seconds (std::clock: the process's, every thread's) since it was made.
struct Timer {
    Clock::time_point wall = Clock::now();
    std::clock_t cpu = std::clock();
    double wallSeconds() const { return std::chrono::duration<double>(Clock::now() - wall).count(); }
    double cpuSecondsSince() const { return double(std::clock() - cpu) / CLOCKS_PER_SEC; }
};

void run(int argc, char** argv) {
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
    if (files.empty())
        for (const auto& entry : std::filesystem::directory_iterator(WOVEN_ASSETS_DIR))
            if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    std::printf("| scene | vertices | sky rays | sky s (cpu) | bounce rays | bounce s (cpu) | woven edit ms |\n");
    std::printf("|---|---:|---:|---|---:|---|---:|\n");
    for (const std::string& file : files) {
        SceneDescription scene = loadScene(file);
        applySceneOptions(scene, FrameOptions{});
        size_t vertices = 0;
        for (const Mesh& m : scene.meshes) vertices += m.positions.size();
        const Timer sky;
        (void)skyVisibility(scene);
        const double skyWall = sky.wallSeconds(), skyCpu = sky.cpuSecondsSince();
        const Timer bounce;
        const BouncedLight bounced = bouncedLight(scene, PreviewLights::fromScene(scene));
        const double bounceWall = bounce.wallSeconds(), bounceCpu = bounce.cpuSecondsSince();
        double editMs = 0.0;
        for (const Material& m : scene.materials)
            if (m.woven) {
                const Timer edit;
                (void)wovenAlbedos(*m.woven);
                editMs = 1e3 * edit.wallSeconds();
                break;
            }
        std::printf("| %s | %zu | %zu | %.2f (%.2f) | %zu | %.2f (%.2f) | %.1f |\n",
                    std::filesystem::path(file).stem().c_str(), vertices, vertices * 2 * kSkyRays, skyWall, skyCpu,
                    bounced.rays, bounceWall, bounceCpu, editMs);
        std::fflush(stdout);
    }
}

}  // namespace
}  // namespace woven

int main(int argc, char** argv) {
    woven::run(argc, argv);
    return 0;
}
