#include "share_page.h"

#include <cstdlib>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "atomic_file.h"
#include "fabric_measures.h"
#include "file_reading.h"
#include "final_preview.h"
#include "image_io.h"
#include "scene_camera.h"
#include "scene_lighting.h"
#include "u3m_export.h"
#include "u3m_physics.h"
#include "weave_construction.h"
#include "weave_pattern.h"

namespace woven {

namespace fs = std::filesystem;

namespace {

void writeBytes(const std::string& path, const std::string& bytes) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp, std::ios::binary);
        f.write(bytes.data(), std::streamsize(bytes.size()));
        if (!f) throw FileWriteError(tmp + ": could not be written");
    });
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(uint8_t(bytes[i])) << 16 | (i + 1 < bytes.size() ? uint32_t(uint8_t(bytes[i + 1])) << 8 : 0) |
                           (i + 2 < bytes.size() ? uint32_t(uint8_t(bytes[i + 2])) : 0);
        out += digits[n >> 18 & 63], out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

// Radiance RGBE, flat scanlines (no run-length coding, which readers need not see): the studio
// environment in the light units woven renders it with.
std::string radianceHdr(const Image& image) {
    std::string out = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(image.height) + " +X " + std::to_string(image.width) + "\n";
    for (const glm::vec3& p : image.pixels) {
        const float m = std::max({p.r, p.g, p.b});
        if (!(m > 1e-32f)) {
            out.append(4, '\0');
            continue;
        }
        int e;
        const float scale = std::frexp(m, &e) * 256.0f / m;
        out += char(uint8_t(p.r * scale)), out += char(uint8_t(p.g * scale)), out += char(uint8_t(p.b * scale)), out += char(uint8_t(e + 128));
    }
    return out;
}

std::string escapeHtml(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// The view the page opens on: the scene's camera, else one framing the woven meshes alone.
Camera clothCamera(const SceneDescription& scene) {
    if (scene.hasCamera) return scene.camera;
    SceneBox box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const Mesh& m : scene.meshes)
        if (m.material >= 0 && scene.materials[size_t(m.material)].woven)
            for (const glm::vec3& p : m.positions)
                if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
    return box.lo.x <= box.hi.x ? framingCamera(box, Camera{}.yfov) : sceneCamera(scene);
}

// model-viewer's camera-target, camera-orbit and field-of-view for `camera`, looking at the
// point of the woven cloth nearest its line of sight (else 1 m ahead).
std::string cameraAttributes(const SceneDescription& scene, const Camera& camera) {
    const glm::vec3 eye(camera.cameraToWorld[3]), forward = -glm::normalize(glm::vec3(camera.cameraToWorld[2]));
    double distance = 0.0, weight = 0.0;
    for (const Mesh& m : scene.meshes)
        if (m.material >= 0 && scene.materials[size_t(m.material)].woven)
            for (const glm::vec3& p : m.positions) {
                const float along = glm::dot(p - eye, forward);
                const float off = glm::length(p - eye - along * forward);
                if (along > 0.0f && off < 0.2f * along) distance += along, weight += 1.0;
            }
    const float d = weight > 0.0 ? float(distance / weight) : 1.0f;
    const glm::vec3 target = eye + d * forward, offset = eye - target;
    const double theta = std::atan2(offset.x, offset.z) * 180.0 / M_PI, phi = std::acos(std::clamp(offset.y / d, -1.0f, 1.0f)) * 180.0 / M_PI;
    char s[400];
    std::snprintf(s, sizeof s,
                  "camera-target=\"%gm %gm %gm\" camera-orbit=\"%gdeg %gdeg %gm\" field-of-view=\"%gdeg\" min-field-of-view=\"1deg\" "
                  "max-field-of-view=\"90deg\" min-camera-orbit=\"auto auto %gm\" max-camera-orbit=\"auto auto %gm\"",
                  target.x, target.y, target.z, theta, phi, d, camera.yfov * 180.0 / M_PI, 0.05 * d, 20.0 * d);
    return s;
}

// One line a woven material: "Cloth: 25 x 16 threads/cm, 381 g/m2, Twill - left hand (S)".
std::string fabricLines(const SceneDescription& scene) {
    std::string html;
    std::vector<int> done;
    for (const Mesh& m : scene.meshes) {
        if (m.material < 0 || !scene.materials[size_t(m.material)].woven || std::find(done.begin(), done.end(), m.material) != done.end()) continue;
        done.push_back(m.material);
        const Material& material = scene.materials[size_t(m.material)];
        std::string line = "<b>" + escapeHtml(material.name) + "</b>: ";
        try {
            const FabricMeasures f = measureSceneMaterial(scene, m.material);
            char s[200];
            std::snprintf(s, sizeof s, "%.4g x %.4g threads/cm, %s%.0f g/m&sup2;, ", f.threadsPerCm.x, f.threadsPerCm.y,
                          f.weightFromWidths ? "about " : "", f.gramsPerSquareMetre);
            line += s;
        } catch (const U3mError&) {
            line += "no real size, ";
        }
        line += u3mConstructionName(construction(WeavePattern::fromParams(*material.woven)));
        html += "<li>" + line + "</li>\n";
    }
    return html;
}

}  // namespace

std::string defaultModelViewer() {
    const char* viewer = std::getenv("WOVEN_MODEL_VIEWER");
    return viewer && *viewer ? viewer : WOVEN_MODEL_VIEWER_JS;
}

std::vector<std::string> writeSharePage(const SceneDescription& scene, const std::string& folder, const ShareOptions& options) {
    std::string viewer;
    try {
        const std::vector<unsigned char> bytes = readRegularFile(options.modelViewer, size_t(64) << 20);
        viewer.assign(bytes.begin(), bytes.end());
    } catch (const FileReadError& e) {
        throw ShareError("woven share needs Google's <model-viewer> script, which it copies into the page, and it is missing (" +
                         std::string(e.what()) + "). Install it with tools/install-deps.sh --share (Debian's npm, then "
                         "npm install --prefix ~ @google/model-viewer), or set WOVEN_MODEL_VIEWER to a copy of "
                         "model-viewer-umd.min.js");
    }
    const fs::path dir(folder);
    std::error_code ec;
    const bool created = !fs::is_directory(dir, ec);
    if (created && !fs::create_directory(dir, ec))
        throw ShareError(folder + ": cannot create the page's folder" + (ec ? " (" + ec.message() + ")" : ""));
    // A failure leaves no index.html (written last), and no folder where it made one and wrote nothing.
    const auto removeIfEmpty = [&] {
        if (created) fs::remove(dir, ec);
    };
    std::vector<std::string> warnings;
    try {
        warnings = exportScene(scene, (dir / "scene.glb").string(), options.exportOptions);
        writeBytes((dir / "model-viewer.min.js").string(), viewer);
        // The poster is seen from where the page opens, so a room around the cloth does not make it a speck either.
        SceneDescription framed = scene;
        framed.camera = clothCamera(scene);
        framed.hasCamera = true;
        const std::vector<unsigned char> poster = encodeTexturePng(renderFinalPreview(framed, options.posterSize, options.posterSpp));
        writeBytes((dir / "poster.png").string(), std::string(poster.begin(), poster.end()));
        const std::string hdr = radianceHdr(*studioEnvironment().image);
        writeBytes((dir / "environment.hdr").string(), hdr);

        const std::vector<unsigned char> glb = readRegularFile((dir / "scene.glb").string(), size_t(1) << 30);
        const std::string title = scene.source.empty() ? "woven" : fs::path(scene.source).stem().string();
        std::ostringstream html;
        html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
             << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
             << "<title>" << escapeHtml(title) << " (woven)</title>\n"
             << "<script src=\"model-viewer.min.js\"></script>\n"
             << "<style>body{margin:0;font:15px/1.4 sans-serif;background:#f4f4f2;color:#222}"
                "model-viewer{width:100vw;height:80vh;background:#fff}#about{padding:0.6em 1em}ul{margin:0.3em 0;padding-left:1.2em}</style>\n"
             << "</head>\n<body>\n"
             // The model and the light inside the page: a page opened from disk may not fetch files
             // beside it. The environment's data URI ends in #.hdr, which model-viewer reads as HDR.
             << "<model-viewer id=\"cloth\" alt=\"" << escapeHtml(title) << "\" src=\"data:model/gltf-binary;base64,"
             << base64(std::string(glb.begin(), glb.end())) << "\" poster=\"poster.png\" environment-image=\"data:application/octet-stream;base64,"
             << base64(hdr) << "#environment.hdr\" camera-controls auto-rotate interaction-prompt=\"none\" "
             << cameraAttributes(scene, clothCamera(scene)) << "></model-viewer>\n"
             << "<div id=\"about\"><ul>\n" << fabricLines(scene) << "</ul>\n"
             << "<small>Rendered by woven; the poster is woven's final frame. Drag to turn, scroll to zoom. "
                "<a href=\"scene.glb\">scene.glb</a></small></div>\n"
             << "<script>document.getElementById('cloth').addEventListener('load',"
                "()=>document.body.setAttribute('data-loaded','yes'));</script>\n"
             << "</body>\n</html>\n";
        writeBytes((dir / "index.html").string(), html.str());
    } catch (const ExportError& e) {
        removeIfEmpty();
        throw ShareError(e.what());
    } catch (const std::exception& e) {
        removeIfEmpty();
        throw ShareError(folder + ": " + e.what());
    }
    return warnings;
}

}  // namespace woven
