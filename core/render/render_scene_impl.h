#pragma once
// RenderScene's insides, shared by the files that build and query it: the Embree scene and its
// queries (render_scene.cpp) and the lights made of the scene's emitters (emissive_lights.cpp).
// Only those include it.
#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bvh_light_sampler.h"
#include "embree_filters.h"
#include "light_sampler.h"
#include "render_scene.h"
#include "scene_loader.h"

namespace woven {

struct RenderScene::Impl {
    std::shared_ptr<const SceneDescription> scene;
    RTCDevice device = nullptr;
    RTCScene rtcScene = nullptr;
    std::string embreeMessage;

    std::optional<SceneMaterials> materials;
    std::vector<HitFilter> hitFilters;  // per mesh, referenced by Embree
    // An instanced mesh's triangles are one Embree scene that each of its copies instances; the
    // copies have the top scene's IDs from meshes.size() on (the other meshes keep their index).
    struct InstanceRef {
        unsigned mesh, instance;
    };
    std::vector<InstanceRef> instanceRefs;  // by instance ID - meshes.size()
    // Some mesh is single-sided: only then do camera rays (and rays towards the camera) take the
    // context filter that culls backs, and the scenes Embree's support for it.
    bool culls = false;
    RTCSceneFlags sceneFlags = RTC_SCENE_FLAG_ROBUST;

    std::vector<Light> lights;
    std::vector<int> directPassLights;
    std::vector<std::vector<int>> triangleLights;  // per mesh: light index per triangle (or empty)
    int environment = -1;
    std::optional<PowerLightSampler> lightSampler;
    std::optional<BvhLightSampler> lightTree;
    Bounds bounds;

    ~Impl() {
        if (rtcScene) rtcReleaseScene(rtcScene);
        if (device) rtcReleaseDevice(device);
    }

    [[noreturn]] void fail(const std::string& what) const { throw SceneError(scene->source + ": " + what); }

    bool tookGeometry = false;  // the BVH is a previous scene's (takeGeometry())

    // glTF's doubleSided false.
    static bool singleSided(const SceneDescription& in, const Mesh& mesh) {
        return mesh.material >= 0 && !in.materials[size_t(mesh.material)].doubleSided;
    }
    bool singleSided(const Mesh& mesh) const { return singleSided(*scene, mesh); }
    void buildGeometry();
    // Whether the Embree scene built for this scene holds `next` (with its materials) as well:
    // what Embree holds of a material is whether its meshes take the pass-through filter and
    // whether they cull backs.
    bool sameGeometry(const SceneDescription& next, const SceneMaterials& nextMaterials) const;
    // The Embree scene of `from`, its hit filters pointed at this scene's meshes and materials.
    void takeGeometry(Impl& from);
    RTCGeometry triangleGeometry(size_t m);
    void addInstances(size_t m, RTCGeometry triangles);
    void buildLights();
    SurfaceHit makeHit(unsigned meshIndex, int instance, unsigned prim, float b1, float b2, float t,
                       const glm::vec3& dir) const;
};

}  // namespace woven
