// What EXT_mesh_gpu_instancing's copies cost: a sphere of 1984 triangles placed 1, 1000 and a
// million times on a grid (a glTF file woven's own writer makes), each count in a fresh process:
// the file's load, the Embree scene's build, the memory both take, and a small frame's render.
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "gltf_writer.h"
#include "render_job.h"
#include "render_scene.h"
#include "scene_camera.h"
#include "scene_loader.h"

using namespace woven;

namespace {

// Resident memory of this process, in MiB.
double residentMiB() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return 0.0;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

Mesh sphere(int rings, int segments) {
    Mesh m;
    m.name = "Ball/0";
    m.meshName = "Ball";
    m.nodePath = {"Balls"};
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = float(M_PI) * float(r) / float(rings), phi = 2.0f * float(M_PI) * float(s) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            m.positions.push_back(0.4f * n);
            m.normals.push_back(n);
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const unsigned a = unsigned(r * (segments + 1) + s), b = a + 1, c = a + unsigned(segments + 1), d = c + 1;
            if (r > 0) m.triangles.emplace_back(a, b, c);
            if (r < rings - 1) m.triangles.emplace_back(b, d, c);
        }
    return m;
}

// One row of the table, measured in this (child) process.
void row(size_t copies, const std::string& file) {
    SceneDescription scene;
    Mesh ball = sphere(32, 32);
    const size_t side = size_t(std::ceil(std::sqrt(double(copies))));
    auto placements = std::make_shared<std::vector<glm::mat4>>();
    for (size_t i = 0; i < copies; ++i) {
        glm::mat4 m(1.0f);
        m[3] = glm::vec4(float(i % side), 0.4f, -float(i / side), 1.0f);
        placements->push_back(m);
    }
    ball.instances = placements;
    scene.meshes = {ball};
    scene.source = "bench";
    const Camera camera = framingCamera(sceneBounds(scene), 0.7f);
    std::vector<std::string> warnings;
    writeGltf(file, scene, camera, warnings);
    const size_t triangles = ball.triangles.size();
    scene = SceneDescription{};
    ball = Mesh{};
    placements.reset();

    const double before = residentMiB();
    auto start = std::chrono::steady_clock::now();
    auto loaded = std::make_shared<SceneDescription>(loadScene(file));
    const double load = seconds(start);
    loaded->environment.color = glm::vec3(1.0f);
    start = std::chrono::steady_clock::now();
    auto embree = std::make_unique<RenderScene>(loaded);
    const double build = seconds(start);
    const double memory = residentMiB() - before;
    const RenderScene::GeometryCounts counts = embree->geometryCounts();
    embree.reset();

    RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.spp = 4;
    s.integrator = "path";
    s.maxDepth = 4;
    s.camera = camera;
    start = std::chrono::steady_clock::now();
    RenderJob job(loaded, s);  // builds its own Embree scene again: part of the render's time
    std::atomic<bool> cancel{false};
    job.run(cancel);
    const double render = seconds(start);
    std::printf("| %zu | %zu | %zu | %.3g | %.2f | %.2f | %.0f | %.2f |\n", copies, counts.triangles, counts.instances,
                double(copies * triangles), load, build, memory, render);
    std::fflush(stdout);
}

}  // namespace

int main() {
    const std::string file = (std::filesystem::temp_directory_path() / ("woven_bench_instancing_" + std::to_string(::getpid()) + ".glb")).string();
    std::printf("EXT_mesh_gpu_instancing: a 1984-triangle sphere placed N times (woven's writer, .glb); load = loadScene, "
                "build = the Embree scene, memory = resident growth over both, render = 160x120, 4 spp, path, "
                "its own Embree build included\n\n");
    std::printf("| instances | triangles held | Embree instances | triangles drawn | load s | build s | memory MiB | render s |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::fflush(stdout);
    for (size_t copies : {size_t(1), size_t(1000), size_t(1000000)}) {
        const pid_t child = fork();
        if (child == 0) {
            try {
                row(copies, file);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "bench_instancing: %s\n", e.what());
                _exit(1);
            }
            _exit(0);
        }
        int status = 0;
        waitpid(child, &status, 0);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
    }
    std::filesystem::remove(file);
    return 0;
}
