#pragma once
// The table of integrators: each once, with the name that --integrator, a scene file's
// render.integrator, `woven converge`, the previewer's menu and a frame's record use, a line for
// --help, and how to make one (as pbrt-v4's Integrator::Create keeps them).
#include <memory>
#include <string>
#include <vector>

namespace woven {

class CameraModel;
class Integrator;
class RenderScene;

struct IntegratorKind {
    const char* name;
    const char* description;
    // maxDepth counts scattering vertices (bounces) as in pbrt-v3: 1 = direct lighting only.
    // filterWeave: woven materials shade each hit filtered over its pixel footprint.
    // Null for auto, which is no integrator but the render job's choice of one of the others by
    // a short pilot of each (render_job.cpp).
    std::unique_ptr<Integrator> (*make)(const RenderScene& scene, const CameraModel& camera, int maxDepth,
                                        bool filterWeave);
};

// In the order `woven converge` compares them and the render job's pilot times them.
const std::vector<IntegratorKind>& integratorKinds();
const IntegratorKind* findIntegrator(const std::string& name);  // null when the table has none
// The entries other code names: auto, and path tracing (the bake report's direct light).
const IntegratorKind& autoIntegrator();
const IntegratorKind& pathIntegrator();

std::vector<std::string> integratorNames();
// "path, bdpt or auto", for messages.
std::string integratorChoices(const char* quote = "");

// A frame's record of its integrator (FrameIdentity::integrator): an integrator's name,
// "auto: NAME" where auto chose it, or "auto" for a merge of frames auto chose differently for.
std::string integratorRecord(const std::string& requested, const std::string& used);
bool isIntegratorRecord(const std::string& record);
bool chosenByAuto(const std::string& record);

}  // namespace woven
