// Throughput of the final-frame renderer: samples per second and rays per second of the path
// tracer and of BDPT at 640x480, against Embree tracing the same scene's triangles with nothing
// else (no filters, no shading), printed as a table with the ratio. Two baselines: coherent
// camera rays (one per pixel, jittered), and the renderer's own rays (bounces, shadow rays,
// BDPT's light paths and connections: incoherent), recorded as it traces a pass and replayed
// in the same order on the same threads, both through bare Embree and through the renderer's
// own Embree scene, whose filter callbacks (woven gaps, alpha) then run too. The scene is
// assets/default_scene.json, or the file given, or, when neither exists, a draped cloth of
// about 15,000 triangles over a box under an area light and a sky.
//
// The renderer's rays are recorded where it calls Embree: this executable defines
// rtcIntersect1 and rtcOccluded1 itself, which the linker binds woven_render's calls to, and
// each passes the call on to Embree's (found with dlsym(RTLD_NEXT)), noting the ray while
// recording. Outside recording that costs an atomic load and an indirect call per ray, about a
// nanosecond against the microseconds of a ray; the baselines call Embree directly.
//
//   bench_render [SCENE] [--spp N] [--threads N]
#include <dlfcn.h>
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "camera_model.h"
#include "render_job.h"
#include "scene_loader.h"

using namespace woven;

namespace {

// One call the renderer made: the ray as it went in, and which query.
struct RecordedRay {
    RTCRay ray;
    bool occlusion;
};

// The rays of each thread, in the order it traced them, while `recording`.
struct RayLog {
    std::atomic<bool> recording{false};
    std::atomic<RTCScene> scene{nullptr};  // the renderer's
    std::mutex mutex;
    std::vector<std::unique_ptr<std::vector<RecordedRay>>> threads;
    int generation = 0;  // of `threads`: a thread's list from an earlier recording is gone

    void note(RTCScene s, const RTCRay& ray, bool occlusion) {
        thread_local std::vector<RecordedRay>* mine = nullptr;
        thread_local int myGeneration = -1;
        if (myGeneration != generation) {
            std::lock_guard<std::mutex> lock(mutex);
            threads.push_back(std::make_unique<std::vector<RecordedRay>>());
            mine = threads.back().get();
            myGeneration = generation;
        }
        scene.store(s, std::memory_order_relaxed);
        mine->push_back({ray, occlusion});
    }
    // Between recordings only, when no thread traces.
    void clear() {
        threads.clear();
        ++generation;
    }
};
RayLog rayLog;

using Intersect1 = void (*)(RTCScene, RTCIntersectContext*, RTCRayHit*);
using Occluded1 = void (*)(RTCScene, RTCIntersectContext*, RTCRay*);
// Embree's own entry points, behind the ones this file defines.
const Intersect1 embreeIntersect1 = reinterpret_cast<Intersect1>(dlsym(RTLD_NEXT, "rtcIntersect1"));
const Occluded1 embreeOccluded1 = reinterpret_cast<Occluded1>(dlsym(RTLD_NEXT, "rtcOccluded1"));

}  // namespace

extern "C" void rtcIntersect1(RTCScene scene, RTCIntersectContext* context, RTCRayHit* rayhit) {
    if (rayLog.recording.load(std::memory_order_relaxed)) rayLog.note(scene, rayhit->ray, false);
    embreeIntersect1(scene, context, rayhit);
}

extern "C" void rtcOccluded1(RTCScene scene, RTCIntersectContext* context, RTCRay* ray) {
    if (rayLog.recording.load(std::memory_order_relaxed)) rayLog.note(scene, *ray, true);
    embreeOccluded1(scene, context, ray);
}

namespace {

using Clock = std::chrono::steady_clock;

// A sheet of 88 x 88 quads (15,488 triangles) hanging over a box, a twill cloth.
SceneDescription drapedClothScene() {
    SceneDescription scene;
    scene.source = "(built-in draped cloth scene)";
    Material cloth;
    cloth.name = "cloth";
    WovenParams p;
    p.pattern = {1, 2, 1};
    p.cy = 0.75f;
    p.noise = 0.2f;
    p.repeat = {60.0f, 60.0f};
    cloth.woven = p;
    Material floor;
    floor.name = "floor";
    floor.baseColor = glm::vec4(glm::vec3(0.5f), 1.0f);
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(8.0f);
    lamp.baseColor = glm::vec4(glm::vec3(0.0f), 1.0f);
    scene.materials = {cloth, floor, lamp};

    constexpr int n = 88;
    Mesh sheet;
    sheet.name = "cloth";
    sheet.material = 0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float u = float(i) / n, v = float(j) / n;
            const float x = 2.4f * u - 1.2f, z = 2.4f * v - 1.2f;
            // Flat on the box top (|x|, |z| < 0.5), falling off towards the floor beyond it.
            const float r = std::max(std::abs(x), std::abs(z));
            const float y = r < 0.5f ? 0.8f : 0.8f - 0.9f * (1.0f - std::exp(-3.0f * (r - 0.5f))) +
                                                  0.04f * std::sin(12.0f * std::atan2(z, x)) * (r - 0.5f);
            sheet.positions.push_back({x, y, z});
            sheet.uvs.push_back({u, v});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const unsigned a = unsigned(j * (n + 1) + i), b = a + 1, c = a + unsigned(n + 1) + 1, d = a + unsigned(n + 1);
            sheet.triangles.push_back({a, d, c});
            sheet.triangles.push_back({a, c, b});
        }
    Mesh ground;
    ground.name = "floor";
    ground.material = 1;
    ground.positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
    ground.triangles = {{0, 2, 1}, {0, 3, 2}};
    Mesh light;
    light.name = "lamp";
    light.material = 2;
    light.positions = {{-0.5f, 2.5f, -0.5f}, {0.5f, 2.5f, -0.5f}, {0.5f, 2.5f, 0.5f}, {-0.5f, 2.5f, 0.5f}};
    light.triangles = {{0, 1, 2}, {0, 2, 3}};
    scene.meshes = {sheet, ground, light};
    scene.environment.color = glm::vec3(0.15f, 0.18f, 0.25f);
    scene.camera.cameraToWorld =
        glm::inverse(glm::lookAt(glm::vec3(0.0f, 1.8f, 3.2f), glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, 1, 0)));
    scene.camera.yfov = 0.8f;
    scene.hasCamera = true;
    return scene;
}

struct Rates {
    double samplesPerSecond = 0.0, raysPerSecond = 0.0, seconds = 0.0;
    int spp = 0;
};

Rates renderRates(const std::shared_ptr<const SceneDescription>& scene, const char* integrator, int spp, int threads) {
    RenderSettings s;
    s.integrator = integrator;
    s.spp = spp;
    s.threads = threads;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    Rates r;
    job.run(cancel, [&](const RenderProgress& p) {
        r.samplesPerSecond = p.samplesPerSecond;
        r.raysPerSecond = p.raysPerSecond;
        r.seconds = p.elapsed;
        r.spp = p.samplesDone;
    });
    return r;
}

// The scene's triangles in an Embree scene of their own: no filters, no user data.
RTCScene bareScene(RTCDevice device, const SceneDescription& scene) {
    RTCScene rtc = rtcNewScene(device);
    for (const Mesh& mesh : scene.meshes) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.positions.size()));
        std::memcpy(v, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.triangles.size()));
        std::memcpy(t, mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3));
        rtcCommitGeometry(g);
        rtcAttachGeometry(rtc, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(rtc);
    return rtc;
}

// Camera rays (one per pixel per pass, jittered) into the scene's triangles with rtcIntersect1
// and nothing else, on the same number of threads.
double bareIntersectRate(const SceneDescription& scene, const Camera& camera, int passes, int threads) {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene rtc = bareScene(device, scene);
    constexpr int width = 640, height = 480;
    const CameraModel model(camera, width, height);
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    std::atomic<long> hits{0};
    const auto start = Clock::now();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, height * passes), [&](const tbb::blocked_range<int>& rows) {
            RTCIntersectContext context;
            long localHits = 0;
            for (int row = rows.begin(); row != rows.end(); ++row) {
                const int y = row % height, pass = row / height;
                for (int x = 0; x < width; ++x) {
                    const float jx = float((x * 7 + pass * 13) % 16) / 16.0f, jy = float((y * 5 + pass * 11) % 16) / 16.0f;
                    const Ray ray = model.generateRay({x + jx, y + jy});
                    rtcInitIntersectContext(&context);
                    RTCRayHit rh{};
                    rh.ray.org_x = ray.o.x; rh.ray.org_y = ray.o.y; rh.ray.org_z = ray.o.z;
                    rh.ray.dir_x = ray.d.x; rh.ray.dir_y = ray.d.y; rh.ray.dir_z = ray.d.z;
                    rh.ray.tnear = 0.0f;
                    rh.ray.tfar = INFINITY;
                    rh.ray.mask = ~0u;
                    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                    embreeIntersect1(rtc, &context, &rh);
                    localHits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                }
            }
            hits += localHits;
        });
    });
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    rtcReleaseScene(rtc);
    rtcReleaseDevice(device);
    if (hits == 0) std::cerr << "bench_render: warning: no camera ray hit the scene\n";
    return double(width) * height * passes / seconds;
}

// Rays per second of Embree on `rays` in `scene`: each thread's rays in their order, the threads
// in parallel as they were when the renderer traced them; the best of three runs.
double replayRate(RTCScene scene, const std::vector<std::unique_ptr<std::vector<RecordedRay>>>& rays, int threads) {
    size_t total = 0;
    for (const auto& list : rays) total += list->size();
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    double best = 0.0;
    for (int run = 0; run < 3; ++run) {
        const auto start = Clock::now();
        arena.execute([&] {
            tbb::parallel_for(size_t(0), rays.size(), [&](size_t list) {
                RTCIntersectContext context;
                for (const RecordedRay& r : *rays[list]) {
                    rtcInitIntersectContext(&context);
                    if (r.occlusion) {
                        RTCRay ray = r.ray;
                        embreeOccluded1(scene, &context, &ray);
                    } else {
                        RTCRayHit rh{};
                        rh.ray = r.ray;
                        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        embreeIntersect1(scene, &context, &rh);
                    }
                }
            });
        });
        best = std::max(best, double(total) / std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

struct ReplayRates {
    size_t rays = 0, occlusion = 0;
    double withFilters = 0.0, bare = 0.0;  // rays/s
};

// Records the rays of one pass of `integrator`, then replays them through the renderer's Embree
// scene (filters on) and through a bare one.
ReplayRates replayRenderersRays(const std::shared_ptr<const SceneDescription>& scene, const char* integrator, int threads) {
    RenderSettings s;
    s.integrator = integrator;
    s.spp = 1;
    s.threads = threads;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    rayLog.clear();
    rayLog.recording = true;
    job.run(cancel);
    rayLog.recording = false;
    ReplayRates r;
    for (const auto& list : rayLog.threads) {
        r.rays += list->size();
        for (const RecordedRay& ray : *list) r.occlusion += ray.occlusion;
    }
    r.withFilters = replayRate(rayLog.scene.load(), rayLog.threads, threads);
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene bare = bareScene(device, *scene);
    r.bare = replayRate(bare, rayLog.threads, threads);
    rtcReleaseScene(bare);
    rtcReleaseDevice(device);
    rayLog.clear();
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::string path;
    int spp = 4, threads = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--spp" && i + 1 < argc) spp = std::atoi(argv[++i]);
        else if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (!a.empty() && a[0] != '-') path = a;
        else {
            std::cerr << "usage: bench_render [SCENE] [--spp N] [--threads N]\n";
            return 2;
        }
    }
    if (path.empty() && std::filesystem::exists(WOVEN_DEFAULT_SCENE)) path = WOVEN_DEFAULT_SCENE;
    std::shared_ptr<SceneDescription> scene;
    try {
        scene = std::make_shared<SceneDescription>(path.empty() ? drapedClothScene() : loadScene(path));
    } catch (const std::exception& e) {
        std::cerr << "bench_render: " << e.what() << "\n";
        return 1;
    }
    size_t triangles = 0;
    for (const Mesh& m : scene->meshes) triangles += m.triangles.size();
    std::printf("scene %s (%zu triangles), 640x480, %d spp, %u hardware threads%s\n\n", scene->source.c_str(),
                triangles, spp, std::thread::hardware_concurrency(), threads > 0 ? (" (" + std::to_string(threads) + " used)").c_str() : "");

    const Rates path_ = renderRates(scene, "path", spp, threads);
    const Rates bdpt = renderRates(scene, "bdpt", spp, threads);
    Camera camera = scene->camera;
    if (!scene->hasCamera) {
        // The render job frames a camera-less scene itself; the bare rays need the same view.
        std::cerr << "bench_render: the scene has no camera; bare rays use the default camera\n";
    }
    const double bare = bareIntersectRate(*scene, camera, 8, threads);
    const ReplayRates pathRays = replayRenderersRays(scene, "path", threads);
    const ReplayRates bdptRays = replayRenderersRays(scene, "bdpt", threads);

    std::printf("| measurement | samples/s | rays/s | rays/s vs bare rtcIntersect1, camera rays | vs bare Embree on the "
                "renderer's own rays |\n|---|---:|---:|---:|---:|\n");
    std::printf("| path tracer (%d spp, %.2f s) | %.0f | %.0f | %.3f | %.3f |\n", path_.spp, path_.seconds,
                path_.samplesPerSecond, path_.raysPerSecond, path_.raysPerSecond / bare, path_.raysPerSecond / pathRays.bare);
    std::printf("| BDPT (%d spp, %.2f s) | %.0f | %.0f | %.3f | %.3f |\n", bdpt.spp, bdpt.seconds, bdpt.samplesPerSecond,
                bdpt.raysPerSecond, bdpt.raysPerSecond / bare, bdpt.raysPerSecond / bdptRays.bare);
    std::printf("| bare rtcIntersect1, camera rays | - | %.0f | 1 | |\n", bare);
    for (const auto& [name, r] : {std::pair<const char*, const ReplayRates&>{"path tracer", pathRays}, {"BDPT", bdptRays}}) {
        std::printf("| the %s's rays (one pass: %zu, %.0f%% shadow), Embree with woven's filters | - | %.0f | %.3f | %.3f |\n",
                    name, r.rays, 100.0 * double(r.occlusion) / double(std::max<size_t>(r.rays, 1)), r.withFilters,
                    r.withFilters / bare, r.withFilters / r.bare);
        std::printf("| the %s's rays, bare Embree | - | %.0f | %.3f | 1 |\n", name, r.bare, r.bare / bare);
    }
    return 0;
}
