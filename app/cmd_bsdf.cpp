// `woven bsdf-eval` (JSON lines in, JSON lines out) and `woven bsdf-plot` (a PNG of the lobe).
#include <stb/stb_image_write.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "bsdf_eval.h"
#include "commands.h"
#include "number_checks.h"
#include "frame_io.h"
#include "output_path.h"
#include "untrusted_json.h"
#include "woven_material.h"

namespace woven {

namespace {

// The next line of `in` (without its newline) into `line`, of which at most `keep` bytes are
// kept: a line without end must not fill the memory. False at the end of the input.
bool readLine(std::streambuf& in, std::string& line, size_t keep) {
    line.clear();
    int c = in.sbumpc();
    if (c == std::char_traits<char>::eof()) return false;
    for (; c != std::char_traits<char>::eof() && c != '\n'; c = in.sbumpc())
        if (line.size() < keep) line.push_back(char(c));
    return true;
}

int runBsdfEval() {
    BsdfEval eval;
    std::string line;
    int lineNumber = 0, errors = 0;
    // One byte past the limit is kept, so that answer() sees the line is too long.
    while (readLine(*std::cin.rdbuf(), line, kMaxBsdfEvalLineBytes + 1)) {
        ++lineNumber;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        try {
            std::cout << eval.answer(line) << "\n";
        } catch (const std::exception& e) {
            // One output line per input line, so a caller can still pair them up.
            const std::string message = "stdin line " + std::to_string(lineNumber) + ": " + e.what();
            std::cout << nlohmann::json{{"error", message}}.dump() << "\n";
            std::cerr << "woven bsdf-eval: error: " << message << "\n";
            ++errors;
        }
    }
    std::cout.flush();
    return errors ? 1 : 0;
}

// A perceptual heat map (black - red - yellow - white) for the plot.
glm::vec3 heat(float x) {
    x = glm::clamp(x, 0.0f, 1.0f);
    return glm::clamp(glm::vec3(3.0f * x, 3.0f * x - 1.0f, 3.0f * x - 2.0f), 0.0f, 1.0f);
}

// The centre of the first element of the tile whose top yarn is `type`, if any.
std::optional<glm::dvec2> elementCentre(const WovenMaterial& m, YarnType type) {
    const WeavePattern& p = m.pattern(false);
    for (int V = 0; V < p.height(); ++V)
        for (int U = 0; U < p.width(); ++U)
            if (p.top(U, V) == type)
                return glm::dvec2((U + 0.5) / m.params().repeat.x, (V + 0.5) / m.params().repeat.y);
    return std::nullopt;
}

void runBsdfPlot(const std::string& materialText, float thetaDeg, float phiDeg, int size, const std::string& out) {
    if (lowerExtension(out) != ".png")
        throw std::invalid_argument(out + ": bsdf-plot writes PNG: the output's name must end in .png");
    checkOutput(out);
    nlohmann::json j;
    try {
        j = materialText.empty() ? nlohmann::json::object() : parseUntrustedJson(materialText);
    } catch (const std::exception& e) {
        throw std::invalid_argument(std::string("--material: ") + e.what());
    }
    const WovenMaterial material(flatSurfaceParams(j));
    const float theta = glm::radians(thetaDeg), phi = glm::radians(phiDeg);
    const glm::vec3 wo(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));

    // One panel per yarn type: f(wo, wi) cos(wi) over the hemisphere of wi, seen from above
    // (orthographic: x = +u to the right, y = +v up). Weft and warp lobes are the same lobe
    // turned by 90 degrees, which is the alternating anisotropy.
    const YarnType types[2] = {YarnType::Weft, YarnType::Warp};
    const int width = 2 * size;
    std::vector<float> value(size_t(width) * size, -1.0f);
    float maxValue = 0.0f;
    for (int panel = 0; panel < 2; ++panel) {
        const auto centre = elementCentre(material, types[panel]);
        if (!centre) continue;
        ShadingInput in;
        in.uv = *centre;
        const auto shading = material.shade(in);
        if (!shading) continue;
        for (int py = 0; py < size; ++py)
            for (int px = 0; px < size; ++px) {
                const float x = (px + 0.5f) / size * 2.0f - 1.0f, y = 1.0f - (py + 0.5f) / size * 2.0f;
                const float r2 = x * x + y * y;
                if (r2 >= 1.0f) continue;
                const glm::vec3 wi(x, y, std::sqrt(1.0f - r2));
                const float v = glm::dot(shading->bsdf.eval(wo, wi), glm::vec3(1.0f / 3.0f)) * wi.z;
                value[size_t(py) * width + panel * size + px] = v;
                maxValue = std::max(maxValue, v);
            }
    }
    std::vector<unsigned char> rgb(size_t(width) * size * 3, 40);
    for (size_t i = 0; i < value.size(); ++i) {
        if (value[i] < 0.0f) continue;
        // Square-root scale so the diffuse floor and the specular peak both show.
        const glm::vec3 c = heat(maxValue > 0.0f ? std::sqrt(value[i] / maxValue) : 0.0f);
        for (int k = 0; k < 3; ++k) rgb[i * 3 + k] = (unsigned char)std::lround(c[k] * 255.0f);
    }
    writeFileAtomically(out, [&](const std::string& tmp) {
        if (!stbi_write_png(tmp.c_str(), width, size, 3, rgb.data(), width * 3)) throw std::runtime_error("cannot write the PNG data");
    });
    std::cerr << "wrote " << out << " (left: weft element, right: warp element; f cos over the hemisphere of wi, "
              << "x = +u, y = +v, peak f cos = " << maxValue << ")\n";
}

}  // namespace

void addBsdfCommands(CLI::App& app) {
    CLI::App* eval = app.add_subcommand(
        "bsdf-eval",
        "Evaluate the woven BSDF: JSON lines on stdin {\"material\":{...},\"uv\":[u,v],\"wi\":[x,y,z],\"wo\":[x,y,z]},\n"
        "one line out each {\"f\":[r,g,b],\"pdf\":p,\"yarn\":\"weft|warp|gap\"}. Local frame: normal +z, dp/du +x,\n"
        "dp/dv +y. f excludes the cosine; pdf is the density of sampling wi given wo.");
    eval->callback([] {
        if (int rc = runBsdfEval()) throw CLI::RuntimeError(rc);
    });

    struct PlotOptions {
        std::string material, out = "lobe.png";
        float theta = 45.0f, phi = 0.0f;
        int size = 256;
    };
    auto opts = std::make_shared<PlotOptions>();
    CLI::App* plot = app.add_subcommand("bsdf-plot", "Write a PNG of the lobe f cos over the hemisphere, weft and warp");
    plot->add_option("--material", opts->material, "woven material as JSON (bsdf-eval's names)");
    plot->add_option("--theta", opts->theta, "polar angle of wo in degrees")->check(finiteNumber(0.0, 89.9));
    plot->add_option("--phi", opts->phi, "azimuth of wo in degrees, 0 = +u")->check(finiteNumber());
    plot->add_option("--size", opts->size, "pixels per panel")->transform(wholeNumber(16, 4096));
    plot->add_option("-o,--out", opts->out, "output PNG");
    plot->callback([opts] { runBsdfPlot(opts->material, opts->theta, opts->phi, opts->size, opts->out); });
}

}  // namespace woven
