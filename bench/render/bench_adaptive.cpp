// The effect of adaptive sampling (--noise-threshold) at equal render time: for each scene and
// integrator, renders with uniform sampling and with adaptive sampling at several thresholds,
// measures each one's relative MSE against a converged, uniformly sampled reference (as
// `woven converge` measures it) and its CPU time. Uniform sampling's relMSE falls as 1 / time
// (less what a render costs whatever its samples: auto's pilot), which gives its relMSE at the
// time each adaptive render took; the table's last column is the ratio of the two, uniform's
// over adaptive's: above 1, adaptive sampling wins. The reference (many samples, uniformly) is
// cached in --out-dir, and the relMSE its own noise adds is taken off every measurement.
// With --samplers and a list of --spp, it also measures the samplers against each other: every
// row's last column is then against the first sampler's uniform render at the first spp.
//
//   bench_adaptive [SCENE...] [--width 160] [--height 120] [--spp 64[,256...]] [--max-spp 256]
//                  [--samplers sobol[,independent]] [--max-depth 8]
//                  [--thresholds 0.02,0.05,0.1] [--integrators path,bdpt,auto]
//                  [--reference-spp 4096] [--reference-integrator path] [--threads 0] [--out-dir DIR]
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "frame_io.h"
#include "image_io.h"
#include "render_job.h"
#include "scene_loader.h"

using namespace woven;

namespace {

struct Options {
    std::vector<std::string> scenes;
    int width = 160, height = 120, maxSpp = 256, referenceSpp = 4096, threads = 0, maxDepth = RenderSettings().maxDepth;
    std::vector<int> spps{64};
    std::vector<std::string> samplers{"sobol"};
    std::string referenceIntegrator = "path";
    std::vector<double> thresholds{0.02, 0.05, 0.1};
    std::vector<std::string> integrators{"path", "bdpt", "auto"};
    std::string outDir = "bench_adaptive";
};

double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Run {
    FilmImage film;
    double cpu = 0.0, wall = 0.0;  // seconds
    std::string integrator;
};

// The reference is sampled independently, so that its halves' difference tells its noise.
Run render(const std::shared_ptr<const SceneDescription>& scene, const Options& o, const std::string& integrator, int spp,
           double threshold, uint64_t seed, int firstSample = 0, SamplerKind sampler = SamplerKind::Independent) {
    RenderSettings s = defaultRenderSettings(*scene);
    s.sampler = sampler;
    s.maxDepth = o.maxDepth;
    s.width = o.width;
    s.height = o.height;
    s.spp = spp;
    s.integrator = integrator;
    s.seed = seed;
    s.firstSample = firstSample;
    s.threads = o.threads;
    s.noiseThreshold = threshold;
    RenderJob job(scene, s);
    std::atomic<bool> cancel{false};
    const double cpu0 = cpuSeconds();
    const auto wall0 = std::chrono::steady_clock::now();
    job.run(cancel);
    Run r;
    r.cpu = cpuSeconds() - cpu0;
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    r.film = job.snapshot();
    r.integrator = job.integratorName();
    return r;
}

// Mean of (x - r)^2 / (r^2 + 0.01) over pixels and channels: woven converge's relMSE, in which
// the 0.01 keeps black reference pixels from dominating (as in Rousselle et al.).
double relativeMse(const Image& image, const Image& reference) {
    double sum = 0.0;
    for (size_t i = 0; i < reference.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double r = reference.pixels[i][c], d = double(image.pixels[i][c]) - r;
            sum += d * d / (r * r + 1e-2);
        }
    return sum / (3.0 * double(reference.pixels.size()));
}

// The reference, and the relMSE its own noise adds to every measurement (which the table takes
// off): rendered as two halves of its samples, whose difference tells their variance.
struct Reference {
    Image image;
    double noise = 0.0;
};

Reference reference(const std::shared_ptr<const SceneDescription>& scene, const Options& o, const std::string& stem) {
    namespace fs = std::filesystem;
    FilmImage halves[2];
    for (int h = 0; h < 2; ++h) {
        std::ostringstream name;
        name << stem << "_" << o.width << "x" << o.height << "_" << o.referenceIntegrator << "_" << o.referenceSpp
             << "spp_d" << o.maxDepth << "_reference_" << h << ".exr";
        const fs::path path = fs::path(o.outDir) / name.str();
        if (fs::exists(path)) {
            const ExrImage exr = readExr(path.string());
            halves[h] = {exr.image, exr.sampleCount, exr.sampleSums, *exr.samples};
            continue;
        }
        std::cerr << "bench_adaptive: rendering " << path.string() << "\n";
        const Run r = render(scene, o, o.referenceIntegrator, o.referenceSpp / 2, 0.0, 0x5eed0001, h * (o.referenceSpp / 2));
        fs::create_directories(o.outDir);
        writeExr(path.string(), r.film.exr(), ExrPrecision::Float);
        std::cerr << "bench_adaptive: took " << r.wall << " s\n";
        halves[h] = r.film;
    }
    Reference ref;
    ref.image = halves[0].radiance;
    double noise = 0.0;
    for (size_t i = 0; i < ref.image.pixels.size(); ++i) {
        ref.image.pixels[i] = 0.5f * (halves[0].radiance.pixels[i] + halves[1].radiance.pixels[i]);
        for (int c = 0; c < 3; ++c) {
            // The mean of two independent halves has a quarter of their squared difference as variance.
            const double d = double(halves[0].radiance.pixels[i][c]) - halves[1].radiance.pixels[i][c];
            const double r = ref.image.pixels[i][c];
            noise += 0.25 * d * d / (r * r + 1e-2);
        }
    }
    ref.noise = noise / (3.0 * double(ref.image.pixels.size()));
    return ref;
}

double meanSamples(const FilmImage& film) {
    double sum = 0.0;
    for (float n : film.sampleCount) sum += n;
    return sum / double(film.sampleCount.size());
}

template <typename T>
std::vector<T> parseList(const std::string& text) {
    std::vector<T> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::stringstream v(item);
        T value{};
        v >> value;
        values.push_back(value);
    }
    return values;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--width" && hasValue) o.width = std::atoi(argv[++i]);
        else if (a == "--samplers" && hasValue) o.samplers = parseList<std::string>(argv[++i]);
        else if (a == "--max-depth" && hasValue) o.maxDepth = std::atoi(argv[++i]);
        else if (a == "--height" && hasValue) o.height = std::atoi(argv[++i]);
        else if (a == "--spp" && hasValue) o.spps = parseList<int>(argv[++i]);
        else if (a == "--max-spp" && hasValue) o.maxSpp = std::atoi(argv[++i]);
        else if (a == "--reference-spp" && hasValue) o.referenceSpp = std::atoi(argv[++i]);
        else if (a == "--reference-integrator" && hasValue) o.referenceIntegrator = argv[++i];
        else if (a == "--threads" && hasValue) o.threads = std::atoi(argv[++i]);
        else if (a == "--thresholds" && hasValue) o.thresholds = parseList<double>(argv[++i]);
        else if (a == "--integrators" && hasValue) o.integrators = parseList<std::string>(argv[++i]);
        else if (a == "--out-dir" && hasValue) o.outDir = argv[++i];
        else if (!a.empty() && a[0] != '-') o.scenes.push_back(a);
        else {
            std::cerr << "usage: bench_adaptive [SCENE...] [--width N] [--height N] [--spp N,N] [--max-spp N] "
                         "[--samplers sobol,independent] [--max-depth N] "
                         "[--thresholds T,T] [--integrators path,bdpt,auto] [--reference-spp N] [--reference-integrator path|bdpt] "
                         "[--threads N] "
                         "[--out-dir DIR]\n";
            return 2;
        }
    }
    if (o.scenes.empty())
        o.scenes = {std::string(WOVEN_ASSETS_DIR) + "/paper_d_satin.json", std::string(WOVEN_ASSETS_DIR) + "/default_scene.json"};

    std::printf("%dx%d, max depth %d; adaptive: at most %d spp; reference: %s, %d spp, independent samples; time: CPU "
                "seconds of the render (all threads)\n\n",
                o.width, o.height, o.maxDepth, o.maxSpp, o.referenceIntegrator.c_str(), o.referenceSpp);
    std::printf("| scene | integrator | sampler | sampling | mean spp | CPU s | wall s | relMSE | relMSE at equal time, %s "
                "uniform at %d spp / this |\n"
                "|---|---|---|---|---:|---:|---:|---:|---:|\n", o.samplers.front().c_str(), o.spps.front());
    for (const std::string& file : o.scenes) {
        std::shared_ptr<const SceneDescription> scene;
        try {
            scene = std::make_shared<const SceneDescription>(loadScene(file));
        } catch (const std::exception& e) {
            std::cerr << "bench_adaptive: " << e.what() << "\n";
            return 1;
        }
        const std::string stem = std::filesystem::path(file).stem().string();
        const Reference ref = reference(scene, o, stem);
        std::printf("| %s | reference | independent | %s, %d spp | | | | %.3e (its noise, taken off the others) | |\n", stem.c_str(),
                    o.referenceIntegrator.c_str(), o.referenceSpp, ref.noise);
        for (const std::string& integrator : o.integrators) {
            uint64_t seed = 1;
            // What a render costs whatever its samples (auto's pilot), which the 1 / time law
            // of uniform sampling's relMSE leaves out.
            const double fixed = render(scene, o, integrator, 0, 0.0, seed).cpu;
            const SamplerKind first = samplerKind(o.samplers.front());
            const Run uniform = render(scene, o, integrator, o.spps.front(), 0.0, seed, 0, first);
            const double uniformMse = relativeMse(uniform.film.radiance, ref.image) - ref.noise;
            const auto row = [&](const Run& r, SamplerKind sampler, const std::string& sampling) {
                const double mse = relativeMse(r.film.radiance, ref.image) - ref.noise;
                const std::string name = integrator == r.integrator ? integrator : integrator + " (" + r.integrator + ")";
                std::printf("| %s | %s | %s | %s | %.1f | %.2f | %.2f | %.3e | %.2f |\n", stem.c_str(), name.c_str(),
                            samplerName(sampler), sampling.c_str(), meanSamples(r.film), r.cpu, r.wall, mse,
                            uniformMse * (uniform.cpu - fixed) / (r.cpu - fixed) / mse);
                std::fflush(stdout);
            };
            for (const std::string& samplerText : o.samplers) {
                const SamplerKind sampler = samplerKind(samplerText);
                for (int spp : o.spps)
                    row(sampler == first && spp == o.spps.front() ? uniform
                                                                  : render(scene, o, integrator, spp, 0.0, seed, 0, sampler),
                        sampler, "uniform");
                for (double t : o.thresholds) {
                    char label[64];
                    std::snprintf(label, sizeof label, "T = %g", t);
                    row(render(scene, o, integrator, o.maxSpp, t, seed, 0, sampler), sampler, label);
                }
            }
        }
    }
    return 0;
}
