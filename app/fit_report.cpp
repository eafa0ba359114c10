#include "fit_report.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "display_transform.h"
#include "fit_loss.h"
#include "image_stats.h"
#include "output_path.h"
#include "shell_quote.h"
#include "twill_direction.h"
#include "weave_candidates.h"

namespace woven {

namespace {

namespace fs = std::filesystem;

Image sideBySide(const Image& a, const Image& b) {
    constexpr int kGap = 4;
    Image out;
    out.width = a.width + kGap + b.width;
    out.height = std::max(a.height, b.height);
    out.pixels.assign(size_t(out.width) * out.height, glm::vec3(1.0f));
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) out.at(x, y) = a.at(x, y);
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x) out.at(a.width + kGap + x, y) = b.at(x, y);
    return out;
}

void writeText(const fs::path& path, const std::string& text) {
    writeFileAtomically(path.string(), [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << text;
        if (!f) throw std::runtime_error("cannot be written");
    });
}

std::string shotPng(size_t i) { return "shot_" + std::to_string(i) + ".png"; }

}  // namespace

void checkFitReport(const std::string& dir, size_t shots) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw FileWriteError(dir + ": --report: is a file: --report names the folder the report goes to");
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir, ec)) throw FileWriteError(dir + ": --report: cannot make the folder" + (ec ? ": " + ec.message() : ""));
    std::vector<std::string> names = {"report.txt", "loss.csv", "loss.gp", "loss.png"};
    for (size_t i = 0; i < shots; ++i) names.push_back(shotPng(i));
    for (const std::string& name : names) checkOutput((fs::path(dir) / name).string());
}

std::vector<std::string> writeFitReport(const std::string& dir, const std::vector<Shot>& shots, const FitResult& result) {
    std::vector<std::string> warnings;
    checkFitReport(dir, shots.size());
    std::ostringstream text;
    text << "weave " << describeWeave(result.params.pattern) << ", repeat " << result.params.repeat.x << " x "
         << result.params.repeat.y << " per UV unit, loss " << result.loss << ", " << result.evaluations << " renders";
    if (result.exposure != 1.0) text << ", exposure " << result.exposure;
    text << "\n";
    for (size_t i = 0; i < shots.size() && i < result.shots.size(); ++i) {
        const ShotFit& f = result.shots[i];
        const std::string png = shotPng(i);
        if (!f.render.pixels.empty())
            writePng((fs::path(dir) / png).string(), sideBySide(shots[i].image, f.render), {0.0f, ToneMap::Clamp});
        text << "\n" << shots[i].path
             << (f.render.pixels.empty() ? std::string(" (no render of the fit finished within its time: no ") + png + ")\n"
                                         : " (" + png + ": photo left, fit right)\n");
        for (int g = 0; g < kStatGroupCount; ++g)
            text << "  " << statGroupNames()[size_t(g)] << " error " << f.terms.error[size_t(g)] << "\n";
        if (f.lambertianBlockMeansError >= 0.0)
            text << "  block means error of the best Lambertian plane under the same light "
                 << f.lambertianBlockMeansError << " (the fit's above " << f.terms.error[kStatBlockMeans] << ")\n";
        if (!f.render.pixels.empty()) {
            // What a person compares first: the mean colour, the shading against a flat image of
            // that colour, and which way the lines of a twill run.
            const std::vector<float> photoBlocks = blockMeans(shots[i].image);
            const glm::dvec3 photoMean = channelMeans(photoBlocks, 1), renderMean = channelMeans(blockMeans(f.render), 1);
            const glm::dvec3 off = 100.0 * (renderMean - photoMean) / glm::max(photoMean, glm::dvec3(1e-30));
            text << "  mean colour, photo (" << photoMean.r << ", " << photoMean.g << ", " << photoMean.b << ") render ("
                 << renderMean.r << ", " << renderMean.g << ", " << renderMean.b << "): " << off.r << ", " << off.g << ", "
                 << off.b << " % off\n";
            std::vector<float> flat(photoBlocks.size());
            for (size_t k = 0; k < flat.size(); ++k) flat[k] = float(photoMean[int(k % 3)]);
            text << "  block means error of a flat image of the photo's mean colour " << colourError(photoBlocks, flat, 1) << "\n";
            text << "  twill lines, degrees from x toward y: photo " << twillLineDegrees(shots[i].image) << ", render "
                 << twillLineDegrees(f.render) << "\n";
        }
        text << "  thread frequency, cycles per pixel: ends photo " << f.photoFrequency.x << " render "
             << f.renderFrequency.x << ", picks photo " << f.photoFrequency.y << " render " << f.renderFrequency.y << "\n";
        text << "  thread direction, render against photo: ends " << f.directionError.x << " degrees, picks "
             << f.directionError.y << " degrees\n";
    }
    writeText(fs::path(dir) / "report.txt", text.str());

    std::ostringstream csv;
    csv << "seconds,loss\n";
    for (const auto& [t, l] : result.history) csv << t << "," << l << "\n";
    const fs::path csvPath = fs::path(dir) / "loss.csv";
    writeText(csvPath, csv.str());
    // A script beside the data, so the plot can be redrawn (and restyled) from the folder alone.
    writeText(fs::path(dir) / "loss.gp",
              "set terminal pngcairo size 640,420 noenhanced\nset output 'loss.png'\nset datafile separator ','\n"
              "set logscale y\nset grid\nset key off\nset xlabel 'time (s)'\nset ylabel 'best loss'\n"
              "set title 'woven fit: the best loss so far'\nplot 'loss.csv' every ::1 using 1:2 with steps lw 2\n");
    const std::string cmd = "cd " + shellQuote(dir) + " && gnuplot loss.gp 2>/dev/null";
    if (std::system(cmd.c_str()) != 0)
        warnings.push_back("gnuplot is not available: wrote " + csvPath.string() + " without loss.png");
    return warnings;
}

}  // namespace woven
