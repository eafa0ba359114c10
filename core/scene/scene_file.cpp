#include "scene_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "coordinate_limits.h"
#include "file_reading.h"
#include "gltf_loader.h"
#include "untrusted_json.h"
#include "image_io.h"
#include "light_limits.h"
#include "woven_assignment.h"
#include "scene_camera.h"
#include "scene_lighting.h"
#include "scene_loader.h"
#include "short_number.h"
#include "woven_params_json.h"

namespace woven {

namespace {

constexpr size_t kMaxSceneFileBytes = size_t(64) << 20;  // far beyond any hand-written scene file

using json = nlohmann::json;
namespace fs = std::filesystem;

class SceneFileReader {
public:
    SceneFileReader(std::string path, const LoadOptions& options) : path_(std::move(path)), options_(options) {}

    SceneDescription read() {
        const json root = parse();
        requireKeys(root, "", {"gltf", "materials", "environment", "lights", "camera", "render", "photo"});
        if (!root.contains("gltf")) fail("gltf", "is missing (the glTF file to load)");
        SceneDescription scene;
        try {
            scene = loadGltf(resolve(string(root["gltf"], "gltf")), options_);
        } catch (const SceneError& e) {
            fail("gltf", e.what());
        }
        scene.source = path_;
        scene.inputFiles.push_back(path_);
        // Lighting the file chose is kept as it is; a file that only makes things woven is lit as
        // its glTF file would be.
        scene.lightingFromSceneFile = root.contains("environment") || root.contains("lights");
        if (root.contains("materials")) readMaterials(root["materials"], scene);
        if (root.contains("environment")) readEnvironment(root["environment"], scene.environment);
        if (root.contains("lights")) readLights(root["lights"], scene.lights);
        if (root.contains("camera")) readCamera(root["camera"], scene);
        if (root.contains("render")) readRender(root["render"], scene.render);
        if (root.contains("photo")) scene.photo = readPhoto(root["photo"]);
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
        throw SceneError(path_ + ": " + (key.empty() ? "" : key + ": ") + problem);
    }

    json parse() const {
        try {
            const std::vector<unsigned char> bytes = readRegularFile(path_, kMaxSceneFileBytes);
            return parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        } catch (const FileReadError& e) {
            throw SceneError(e.what());
        } catch (const std::invalid_argument& e) {
            fail("", e.what());
        }
    }

    // A path in the scene file is relative to the scene file's directory.
    std::string resolve(const std::string& relative) const {
        const fs::path p(relative);
        return p.is_absolute() ? relative : (fs::path(path_).parent_path() / p).string();
    }

    void requireKeys(const json& object, const std::string& where, std::initializer_list<const char*> allowed) const {
        if (!object.is_object()) fail(where, "must be a JSON object");
        for (const auto& item : object.items()) {
            bool known = false;
            for (const char* name : allowed) known |= item.key() == name;
            if (!known) {
                std::string list;
                for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
                fail(key(where, item.key()), "unknown key (expected one of: " + list + ")");
            }
        }
    }

    static std::string key(const std::string& where, const std::string& name) {
        return where.empty() ? name : where + "." + name;
    }

    std::string string(const json& v, const std::string& where) const {
        if (!v.is_string()) fail(where, "must be a string");
        return v.get<std::string>();
    }

    float number(const json& v, const std::string& where) const {
        // Finite as a float too: 1e39 is a finite double but an infinite float.
        if (!v.is_number() || !std::isfinite(v.get<double>()) || !std::isfinite(v.get<float>()))
            fail(where, "must be a finite number");
        return v.get<float>();
    }

    // A finite number from `lo` to `hi`, judged as written: 1e-300 is no "0" (as a float it is).
    float numberIn(const json& v, const std::string& where, double lo, double hi) const {
        const float x = number(v, where);
        const double written = v.get<double>();
        if (!(written >= lo && written <= hi))
            fail(where, "is " + shortNumber(written) + ", must be from " + shortNumber(lo) + " to " + shortNumber(hi));
        return x;
    }

    int positiveInt(const json& v, const std::string& where, int max) const {
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > max)
            fail(where, "must be an integer from 1 to " + std::to_string(max));
        return v.get<int>();
    }

    glm::vec3 vec3(const json& v, const std::string& where) const {
        if (!v.is_array() || v.size() != 3) fail(where, "must be an array of 3 numbers");
        return {number(v[0], where), number(v[1], where), number(v[2], where)};
    }

    // A point in the scene, within woven's coordinate limit.
    glm::vec3 point(const json& v, const std::string& where) const {
        const glm::vec3 p = vec3(v, where);
        if (const std::string problem = coordinateProblem(p); !problem.empty()) fail(where, problem);
        return p;
    }

    // A colour: [r, g, b] or one number for grey, each >= 0.
    glm::vec3 color(const json& v, const std::string& where) const {
        const glm::vec3 c = v.is_number() ? glm::vec3(number(v, where)) : vec3(v, where);
        if (c.x < 0 || c.y < 0 || c.z < 0) fail(where, "must not be negative");
        return c;
    }

    void readMaterials(const json& materials, SceneDescription& scene) const {
        if (!materials.is_object())
            fail("materials", "must be an object from a target (a material, \"mesh:NAME\", \"node:NAME\" or \"*\") to woven parameters");
        std::vector<WovenAssignment> assignments;
        for (const auto& item : materials.items())
            assignments.push_back({item.key(), item.value(), "materials." + item.key(), fs::path(path_).parent_path().string()});
        assignWoven(scene, assignments);
    }

    void readEnvironment(const json& env, Environment& environment) const {
        requireKeys(env, "environment", {"color", "image", "intensity", "rotation"});
        if (env.contains("image")) {
            const std::string image = resolve(string(env["image"], "environment.image"));
            try {
                environment.image = readEnvironmentImage(image);
            } catch (const ImageError& e) {
                fail("environment.image", e.what());
            }
            environment.color = glm::vec3(1.0f);  // the image as it is unless a colour scales it
        }
        if (env.contains("color")) {
            environment.color = color(env["color"], "environment.color");
            if (const std::string problem = lightValueProblem(environment.color); !problem.empty())
                fail("environment.color", problem);
        }
        // A scale of the colour (and image) that keeps its tint: the look-development knob.
        if (env.contains("intensity")) {
            environment.color *= numberIn(env["intensity"], "environment.intensity", 0.0, 1e6);
            if (const std::string problem = lightValueProblem(environment.color); !problem.empty())
                fail("environment.intensity", "times environment.color " + problem);
        }
        if (env.contains("rotation")) environment.rotation = glm::radians(number(env["rotation"], "environment.rotation"));
    }

    void readLights(const json& lights, std::vector<PunctualLight>& out) const {
        if (!lights.is_array()) fail("lights", "must be an array of lights");
        for (size_t i = 0; i < lights.size(); ++i) {
            const std::string where = "lights[" + std::to_string(i) + "]";
            const json& l = lights[i];
            requireKeys(l, where, {"type", "color", "intensity", "position", "direction", "inner_cone_degrees", "outer_cone_degrees"});
            if (!l.contains("type")) fail(where, "needs \"type\": \"point\", \"spot\" or \"directional\"");
            const std::string type = string(l["type"], where + ".type");
            PunctualLight light;
            if (type == "point") light.type = PunctualLight::Type::Point;
            else if (type == "spot") light.type = PunctualLight::Type::Spot;
            else if (type == "directional") light.type = PunctualLight::Type::Directional;
            else fail(where + ".type", "must be \"point\", \"spot\" or \"directional\", not \"" + type + "\"");
            const bool positioned = light.type != PunctualLight::Type::Directional;
            const bool aimed = light.type != PunctualLight::Type::Point;
            if (positioned && !l.contains("position")) fail(where, "a " + type + " light needs \"position\"");
            if (aimed && !l.contains("direction")) fail(where, "a " + type + " light needs \"direction\"");
            if (!positioned && l.contains("position")) fail(where + ".position", "a directional light has no position");
            if (!aimed && l.contains("direction")) fail(where + ".direction", "a point light has no direction");
            if (positioned) light.position = point(l["position"], where + ".position");
            if (aimed) {
                const glm::vec3 d = vec3(l["direction"], where + ".direction");
                if (!(glm::length(d) > 0.0f)) fail(where + ".direction", "must not be zero");
                light.direction = glm::normalize(d);
            }
            const glm::vec3 c = l.contains("color") ? color(l["color"], where + ".color") : glm::vec3(1.0f);
            const float intensity = l.contains("intensity") ? number(l["intensity"], where + ".intensity") : 1.0f;
            if (intensity < 0.0f) fail(where + ".intensity", "must not be negative");
            light.intensity = c * intensity;
            if (const std::string problem = lightValueProblem(light.intensity); !problem.empty())
                fail(where, "color times intensity " + problem);
            const bool coned = l.contains("inner_cone_degrees") || l.contains("outer_cone_degrees");
            if (coned && light.type != PunctualLight::Type::Spot) fail(where, "cone angles are for spot lights");
            if (l.contains("inner_cone_degrees"))
                light.innerConeAngle = glm::radians(number(l["inner_cone_degrees"], where + ".inner_cone_degrees"));
            if (l.contains("outer_cone_degrees"))
                light.outerConeAngle = glm::radians(number(l["outer_cone_degrees"], where + ".outer_cone_degrees"));
            if (!(light.innerConeAngle >= 0.0f && light.innerConeAngle < light.outerConeAngle &&
                  light.outerConeAngle <= glm::radians(90.0f)))
                fail(where, "cone angles must satisfy 0 <= inner < outer <= 90 degrees");
            out.push_back(light);
        }
    }

    void readCamera(const json& cam, SceneDescription& scene) const {
        requireKeys(cam, "camera", {"position", "target", "up", "yfov_degrees"});
        if (!cam.contains("position") || !cam.contains("target")) fail("camera", "needs \"position\" and \"target\"");
        const glm::vec3 position = point(cam["position"], "camera.position");
        const glm::vec3 target = point(cam["target"], "camera.target");
        const glm::vec3 up = cam.contains("up") ? vec3(cam["up"], "camera.up") : glm::vec3(0, 1, 0);
        // In double, as lookAt() works: in float the squared length of a long view overflows (and
        // of a very short one underflows), and any up then looked parallel to it.
        const glm::dvec3 back = glm::dvec3(position) - glm::dvec3(target);
        if (!(glm::length(back) > 0.0)) fail("camera.target", "must differ from camera.position");
        if (!(glm::length(glm::dvec3(up)) > 0.0)) fail("camera.up", "must not be zero");
        if (!(glm::length(glm::cross(glm::normalize(glm::dvec3(up)), glm::normalize(back))) > 1e-6))
            fail("camera.up", "must not be parallel to the view direction");
        if (cam.contains("yfov_degrees")) {
            const float degrees = number(cam["yfov_degrees"], "camera.yfov_degrees");
            if (!(degrees > 0.0f && degrees < 180.0f)) fail("camera.yfov_degrees", "must be between 0 and 180");
            scene.camera = cameraOf({position, target, up, degrees});  // as the previewer saves it
        } else {
            scene.camera = lookAt(position, target, up, scene.camera.yfov);  // the glTF camera's field of view
        }
        scene.camera.aspect = 0.0f;  // the image decides
        scene.hasCamera = true;
    }

    void readRender(const json& render, RenderHints& hints) const {
        requireKeys(render, "render", {"width", "height", "spp", "integrator", "sampler", "noise_threshold"});
        if (render.contains("width")) hints.width = positiveInt(render["width"], "render.width", 16384);
        if (render.contains("height")) hints.height = positiveInt(render["height"], "render.height", 16384);
        if (render.contains("spp")) hints.spp = positiveInt(render["spp"], "render.spp", 1 << 20);
        // Its name is checked against the integrators' table where a render takes it
        // (defaultRenderSettings()), in the render layer above this one.
        if (render.contains("integrator")) hints.integrator = string(render["integrator"], "render.integrator");
        // "sobol" (the default) or "independent", as --sampler; checked as the integrator is.
        if (render.contains("sampler")) hints.sampler = string(render["sampler"], "render.sampler");
        // As --noise-threshold, in double: the previewer saves its Render button's value exactly.
        if (render.contains("noise_threshold")) {
            const json& v = render["noise_threshold"];
            if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= 1.0))
                fail("render.noise_threshold", "must be a number from 0 to 1");
            hints.noiseThreshold = v.get<double>();
        }
    }

    // A shot's photograph, for `woven fit` (docs/FIT.md):
    //   image               the photo's file (PNG, JPEG, EXR, HDR), relative to the scene file; the
    //                       frame at the render's size, opened by the fit only
    //   encoding            "srgb" (default), "gamma2.2" or "linear": how its 8- or 16-bit values
    //                       are linear light (EXR and HDR are linear whatever it says)
    //   vignette_sigma_px   the lens's fall-off toward the corners, a Gaussian of that many pixels
    //                       about the centre, applied to the render before comparing (absent: none)
    //   exposure            a positive number the render is multiplied by (default 1), or "free":
    //                       one exposure, shared by all the fit's free shots, is fitted
    ShotPhoto readPhoto(const json& photo) const {
        requireKeys(photo, "photo", {"image", "encoding", "vignette_sigma_px", "exposure"});
        if (!photo.contains("image")) fail("photo", "needs \"image\": the photograph's file");
        ShotPhoto shot;
        shot.image = resolve(string(photo["image"], "photo.image"));
        if (photo.contains("encoding")) {
            const std::string e = string(photo["encoding"], "photo.encoding");
            if (e == "srgb") shot.encoding = ShotPhoto::Encoding::Srgb;
            else if (e == "gamma2.2") shot.encoding = ShotPhoto::Encoding::Gamma22;
            else if (e == "linear") shot.encoding = ShotPhoto::Encoding::Linear;
            else fail("photo.encoding", "must be \"srgb\", \"gamma2.2\" or \"linear\", not \"" + e + "\"");
        }
        if (photo.contains("vignette_sigma_px")) {
            // Under a pixel the render would be black but for its centre.
            shot.vignetteSigmaPx = numberIn(photo["vignette_sigma_px"], "photo.vignette_sigma_px", 1.0, 1e6);
        }
        if (photo.contains("exposure")) {
            const json& e = photo["exposure"];
            if (e.is_string() && e.get<std::string>() == "free") shot.exposure.reset();
            else if (!e.is_number()) fail("photo.exposure", "must be a positive number or \"free\"");
            else {
                // Twenty stops either way: far past any camera's difference from a render.
                shot.exposure = numberIn(e, "photo.exposure", 1e-6, 1e6);
            }
        }
        return shot;
    }

    std::string path_;
    LoadOptions options_;
};

}  // namespace

SceneDescription loadSceneFile(const std::string& path, const LoadOptions& options) {
    return SceneFileReader(path, options).read();
}

}  // namespace woven
