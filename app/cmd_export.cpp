// `woven bake SCENE -o DIR`: each woven material's glTF textures (and mip levels) as PNG files;
// `woven export SCENE -o OUT.glb`: the scene as a standard glTF file, woven materials baked,
// with --report the bake's error against the model (docs/EXPORT.md).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>

#include "bake_report.h"
#include "commands.h"
#include "fabric_scene.h"
#include "number_checks.h"
#include "flat_cloth.h"
#include "frame_io.h"
#include "gltf_writer.h"
#include "image_io.h"
#include "output_path.h"
#include "progress_bar.h"
#include "scene_camera.h"
#include "scene_export.h"
#include "share_page.h"
#include "u3m_export.h"
#include "woven_assignment.h"

namespace woven {

namespace {

struct ExportCommand {
    std::string scene, out;
    std::vector<std::string> woven;  // TARGET=JSON
    ExportOptions options;
    bool noSheen = false, isotropic = false;
    bool report = false, mips = false;
    ReportOptions reportOptions;
    U3mOptions u3m;
    ShareOptions share;
};

// The scene (or a bare fabric on the drape) with the command line's --woven edits; no default
// lighting (glTF has no place for it).
SceneDescription loadWithEdits(const ExportCommand& o) {
    SceneDescription scene = loadSceneOrFabric(o.scene);
    std::vector<WovenAssignment> assignments;
    for (const std::string& option : o.woven) assignments.push_back(parseWovenOption(scene, option));
    if (!assignments.empty()) assignWoven(scene, assignments);
    return scene;
}

constexpr const char* kSceneHelp =
    "scene file (.gltf, .glb or a woven .json scene file), or a fabric shown on woven's drape: a library fabric's name, a "
    "fabric or material .json, a .wif draft or a .u3ma/.u3m";

void addBakeOptions(CLI::App& cmd, ExportCommand& o) {
    cmd.add_option("--woven", o.woven, "TARGET=JSON: make the parts TARGET names woven first (as woven render's --woven)");
    cmd.add_option("--size", o.options.bake.size, "texels along the longer side of each texture (default 512)")->transform(wholeNumber(4, 16384));
    cmd.add_option("--repeats", o.options.bake.repeats, "weave repeats each texture holds along u and v (default 1)")
        ->transform(wholeNumber(1, 1024));
    cmd.add_flag("--no-sheen", o.noSheen, "fit no KHR_materials_sheen layer");
    cmd.add_flag("--isotropic", o.isotropic,
                 "no KHR_materials_anisotropy: one roughness a texel, for renderers that ignore the extension (Blender 3.4)");
}

// "Cloth [mesh:Sofa]" -> "Cloth__mesh_Sofa_": a file name from a material name.
std::string fileStem(const std::string& name) {
    std::string s;
    for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return s.empty() ? "material" : s;
}

// A progress line per bake: the texels of a large one take minutes.
void showBakeProgress(BakeOptions& bake, const std::shared_ptr<ProgressBar>& bar) {
    bake.progress = [bar](double fraction) {
        bar->update(fraction, std::to_string(int(fraction * 100.0)) + "% of the texels sampled");
    };
}

// One file of a bake: its final name and how it is written (to the name given).
struct BakeFile {
    std::string path;
    std::function<void(const std::string&)> write;
};

// A bake's files all appear, or none does: each is written under its partial name first (those
// written are removed when one fails), then all are renamed into place.
void writeAllOrNone(const std::vector<BakeFile>& files) {
    for (const BakeFile& f : files) {
        checkOutput(f.path);
        checkOutput(partialName(f.path));
    }
    std::vector<std::string> written;
    try {
        for (const BakeFile& f : files) {
            f.write(partialName(f.path));
            written.push_back(partialName(f.path));
        }
    } catch (...) {
        for (const std::string& path : written) std::remove(path.c_str());
        throw;
    }
    for (const BakeFile& f : files)
        if (std::rename(partialName(f.path).c_str(), f.path.c_str()) != 0)
            throw FileWriteError(f.path + ": cannot rename " + partialName(f.path) + " into place: " + std::strerror(errno));
}

void runBake(ExportCommand o) {
    namespace fs = std::filesystem;
    o.options.bake.sheen = !o.noSheen;
    o.options.bake.anisotropy = !o.isotropic;
    const auto bar = std::make_shared<ProgressBar>("bake");
    showBakeProgress(o.options.bake, bar);
    std::error_code ec;
    if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
        throw ExportError(o.out + ": is a file: bake -o names the folder its textures go to");
    if (!fs::is_directory(o.out, ec)) throw ExportError(o.out + ": no such folder (create it first)");
    const SceneDescription scene = loadWithEdits(o);
    std::cerr << "bake: baking the woven materials of " << o.scene << "\n";
    std::vector<MaterialBake> bakes;
    bakedScene(scene, o.options, &bakes);
    bar->finish();
    std::vector<BakeFile> files;
    for (const MaterialBake& b : bakes) {
        const Material& original = scene.materials[size_t(b.material)];
        const std::string stem = (fs::path(o.out) / fileStem(original.name)).string();
        for (int map = 0; map < int(b.baked.textures.size()); ++map) {
            const TextureImage& texture = b.baked.textures[size_t(map)];
            files.push_back({stem + "_" + BakedMaterial::mapName(map) + ".png",
                             [&texture](const std::string& path) { writeTexturePng(path, texture); }});
            if (!o.mips) continue;
            for (size_t level = 0; level < b.baked.mipLevels[size_t(map)].size(); ++level) {
                const TextureImage& mip = b.baked.mipLevels[size_t(map)][level];
                files.push_back({stem + "_" + BakedMaterial::mapName(map) + "_mip" + std::to_string(level + 1) + ".png",
                                 [&mip](const std::string& path) { writeTexturePng(path, mip); }});
            }
        }
        // A square of one texture tile in the material, for any glTF viewer.
        files.push_back({stem + ".gltf", [&o, &b, &original](const std::string& path) {
                             SceneDescription square;
                             square.source = o.scene;
                             square.meshes.push_back(flatCloth(glm::vec2(b.baked.uvSize), fileStem(original.name)));
                             square.materials.push_back(bakedMaterial(original, b.baked, 0));
                             square.textures = b.baked.textures;
                             std::vector<std::string> warnings;
                             writeGltf(path, square, sceneCamera(square), warnings);
                         }});
    }
    writeAllOrNone(files);
    for (const MaterialBake& b : bakes) {
        const Material& original = scene.materials[size_t(b.material)];
        const std::string stem = (fs::path(o.out) / fileStem(original.name)).string();
        std::cout << "material '" << original.name << "': " << b.baked.textures[0].width << "x" << b.baked.textures[0].height
                  << " texels for " << b.baked.threads.x * o.options.bake.repeats << "x" << b.baked.threads.y * o.options.bake.repeats
                  << " threads (" << b.baked.uvSize.x << " x " << b.baked.uvSize.y << " in uv), far-field error "
                  << b.baked.farFieldError << ": " << stem << "_*.png, " << stem << ".gltf\n";
        for (const std::string& note : b.baked.notes) std::cerr << "note: material '" << original.name << "': " << note << "\n";
    }
}

bool isU3m(const std::string& path) {
    const std::string e = lowerExtension(path);
    return e == ".u3ma" || e == ".u3m";
}

// One woven material as a U3M (u3m_export.h), its physics and map size on stdout.
void runU3mExport(ExportCommand o) {
    o.u3m.bake = o.options.bake;
    const auto bar = std::make_shared<ProgressBar>("bake");
    showBakeProgress(o.u3m.bake, bar);
    const SceneDescription scene = loadWithEdits(o);
    checkOutput(o.out);
    std::cerr << "export: baking the front and back of a woven material of " << o.scene << "\n";
    const U3mExport u = exportU3m(scene, o.out, o.u3m);
    bar->finish();
    for (const std::string& note : u.notes) std::cerr << "note: material '" << u.material << "': " << note << "\n";
    const nlohmann::json& physics = u.document["material"]["physics"];
    std::cout << "material '" << u.material << "': " << describe(u.measures) << "; " << physics["construction"]["type"].get<std::string>()
              << ", " << physics["thickness"].get<double>() << " mm thick; maps " << u.mapMm.x << " x " << u.mapMm.y << " mm\n";
    std::cerr << "wrote " << o.out << "\n";
}

void runExport(ExportCommand o) {
    o.options.bake.sheen = !o.noSheen;
    o.options.bake.anisotropy = !o.isotropic;
    if (isU3m(o.out)) return runU3mExport(o);
    const auto bar = std::make_shared<ProgressBar>("bake");
    showBakeProgress(o.options.bake, bar);
    if (!o.reportOptions.imageFolder.empty() && !std::filesystem::is_directory(o.reportOptions.imageFolder))
        throw ExportError(o.reportOptions.imageFolder + ": no such folder (create it first)");
    const SceneDescription scene = loadWithEdits(o);
    checkOutput(o.out);
    std::cerr << "export: baking the woven materials of " << o.scene << "\n";
    std::vector<MaterialBake> bakes;
    const std::vector<std::string> warnings = exportScene(scene, o.out, o.options, &bakes);
    bar->finish();
    for (const std::string& w : warnings) std::cerr << "warning: " << o.out << ": " << w << "\n";
    std::cerr << "wrote " << o.out << "\n";
    if (!o.report) return;
    o.reportOptions.imagePrefix = std::filesystem::path(o.out).stem().string() + "_";
    for (const MaterialBake& b : bakes) {
        std::cerr << "export: rendering the model and the bake of '" << scene.materials[size_t(b.material)].name << "'\n";
        std::cout << formatReport(reportBake(scene.materials[size_t(b.material)], b.baked, o.reportOptions), o.reportOptions);
    }
}

// The page folder of `woven share` (share_page.h).
void runShare(ExportCommand o) {
    o.share.exportOptions = o.options;
    o.share.exportOptions.bake.sheen = !o.noSheen;
    o.share.exportOptions.bake.anisotropy = !o.isotropic;
    const auto bar = std::make_shared<ProgressBar>("bake");
    showBakeProgress(o.share.exportOptions.bake, bar);
    const SceneDescription scene = loadWithEdits(o);
    // A page folder not made yet is made by writeSharePage (its parent must exist); one that is
    // there has each file checked up front.
    std::error_code ec;
    if (std::filesystem::is_directory(o.out, ec))
        for (const char* file : {"index.html", "scene.glb", "poster.png", "environment.hdr", "model-viewer.min.js"})
            checkOutput((std::filesystem::path(o.out) / file).string());
    std::cerr << "share: baking the woven materials of " << o.scene << ", then woven's render for the poster\n";
    const std::vector<std::string> warnings = writeSharePage(scene, o.out, o.share);
    bar->finish();
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    std::cerr << "wrote " << (std::filesystem::path(o.out) / "index.html").string() << "\n";
}

}  // namespace

void addExportCommands(CLI::App& app) {
    auto e = std::make_shared<ExportCommand>();
    CLI::App* cmd = app.add_subcommand("export", "Write a scene as a standard glTF file, each woven material baked to textures");
    cmd->add_option("scene", e->scene, kSceneHelp)->required();
    cmd->add_option("-o,--out", e->out, "the file to write: .glb (binary glTF), .gltf (images embedded), .u3ma (one woven material as a "
                                        "U3M archive) or .u3m (the same as a file and a folder of textures)")->required();
    addBakeOptions(*cmd, *e);
    cmd->add_option("--material", e->u3m.material, "U3M: the woven material to export (default: the scene's only one)");
    cmd->add_option("--preview-size", e->u3m.previewSize, "U3M: pixels along the preview render's longer side (default 256; 0: none)")
        ->transform(wholeNumber(0, 4096));
    cmd->add_option("--preview-spp", e->u3m.previewSpp, "U3M: samples per pixel of the preview render (default 16)")->transform(wholeNumber(1, 1 << 16));
    cmd->add_flag("--keep-woven", e->options.keepWoven, "also keep the woven parameters (WOVEN_fabric), so woven reads the file back as woven");
    cmd->add_flag("--report", e->report, "print the bake's error against the model, rendered near and far, per feature");
    cmd->add_option("--report-spp", e->reportOptions.spp, "samples per pixel of the report's near renders (default 256; the far ones take 16 times as many at a quarter of the size)")->transform(wholeNumber(1, 1 << 16));
    cmd->add_option("--report-images", e->reportOptions.imageFolder, "write the report's renders of the model and the bake as PNGs into this folder (OUT_MATERIAL_near_model.png, ...)");
    cmd->callback([e] { runExport(*e); });

    auto b = std::make_shared<ExportCommand>();
    CLI::App* bake = app.add_subcommand("bake", "Bake each woven material of a scene to glTF textures (PNG) and a sample .gltf");
    bake->add_option("scene", b->scene, kSceneHelp)->required();
    bake->add_option("-o,--out", b->out, "the folder to write into")->required();
    addBakeOptions(*bake, *b);
    bake->add_flag("--mips", b->mips, "also write every mip level, fitted in the model (NAME_MAP_mipN.png)");
    bake->callback([b] { runBake(*b); });

    auto p = std::make_shared<ExportCommand>();
    CLI::App* share = app.add_subcommand("share", "Write a web page that shows the scene's cloth in a browser, offline (model-viewer)");
    share->add_option("scene", p->scene, kSceneHelp)->required();
    share->add_option("-o,--out", p->out, "the page's folder (created if missing): index.html, scene.glb, poster.png, ...")->required();
    addBakeOptions(*share, *p);
    share->add_option("--poster-size", p->share.posterSize, "pixels along the poster render's longer side (default 640)")->transform(wholeNumber(16, 8192));
    share->add_option("--poster-spp", p->share.posterSpp, "samples per pixel of the poster render (default 64)")->transform(wholeNumber(1, 1 << 16));
    share->callback([p] { runShare(*p); });
}

}  // namespace woven
