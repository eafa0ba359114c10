#include "woven_gl_material.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "gltf_gl_material.h"
#include "weave.h"
#include "weave_far_field.h"

namespace woven {

namespace {

const char* glslType(ParamType t) {
    switch (t) {
        case ParamType::Float: return "float";
        case ParamType::Int: return "int";
        case ParamType::Vec2: return "vec2";
        case ParamType::Vec3: return "vec3";
        case ParamType::IVec3: return "ivec3";
        default: return nullptr;  // lists: textures
    }
}

// Everything the tile texture is made of.
bool sameTile(const WovenParams& a, const WovenParams& b) {
    return a.pattern == b.pattern && a.tile == b.tile && (a.crimp > 0.0f) == (b.crimp > 0.0f);
}

// Everything the thread table and the far-field weights are made of, but the yarns' shading
// fields: the tile, the lists, the colours and the widths.
bool sameThreads(const WovenParams& a, const WovenParams& b) {
    return sameTile(a, b) && a.warp_colors == b.warp_colors && a.weft_colors == b.weft_colors &&
           a.warp_yarns == b.warp_yarns && a.weft_yarns == b.weft_yarns && a.warp_spacing == b.warp_spacing &&
           a.weft_spacing == b.weft_spacing && a.warp_color == b.warp_color && a.weft_color == b.weft_color &&
           a.yarn_width == b.yarn_width && a.warp_width == b.warp_width && a.yarns == b.yarns;
}

void uploadBuffer(GLuint buffer, GLuint texture, const std::vector<glm::vec4>& texels) {
    glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(texels.size() * sizeof(glm::vec4)), texels.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glBindTexture(GL_TEXTURE_BUFFER, texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
}

// The 1D colour track of one side for the weave filter, over one period in mean thread widths
// (the shader's e / period): per bin (colour x the length of it in the bin, that length), so a
// filtered lookup is the mean colour over what it covers. A bin per thread for even spacing;
// for uneven spacing up to 8 bins per mean width, each the threads' colours by their overlap,
// so wide and narrow threads keep their places. A period longer than the GPU's widest texture
// gets several threads a bin.
void uploadColorTrack(GLuint texture, const ThreadLayout& side) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const double period = side.period();
    const int bins = side.spaced() ? int(std::min(8.0, std::max(1.0, std::floor(maxSize / period))) * period)
                                   : int(std::min(period, double(maxSize)));
    const double binsPerWidth = bins / period;
    std::vector<glm::vec4> texels(size_t(bins), glm::vec4(0.0f));
    for (int k = 0; k < side.period(); ++k) {
        // The thread's cell in bin units, spread over the bins it overlaps.
        const double begin = (side.spaced() ? side.start(k) : k) * binsPerWidth;
        const double end = begin + (side.spaced() ? side.width(k) : 1.0) * binsPerWidth;
        for (int b = int(begin); b < bins && b < end; ++b) {
            const float overlap = float(std::min(end, b + 1.0) - std::max(begin, double(b)));
            texels[size_t(b)] += glm::vec4(side.color(k) * overlap, overlap);
        }
    }
    glBindTexture(GL_TEXTURE_1D, texture);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA32F, bins, 0, GL_RGBA, GL_FLOAT, texels.data());
    glGenerateMipmap(GL_TEXTURE_1D);
    // Nearest within a level: a footprint inside one bin sees that bin's colour alone, as core's
    // box means do; linear filtering blended each thread with its neighbour over a whole thread
    // (a houndstooth's dark blocks came out a third too bright at 3 pixels a thread).
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glBindTexture(GL_TEXTURE_1D, 0);
}

// The textures of what a glTF material made woven keeps, in maps[] order.
std::vector<MapUse> keptSurfaceMaps(const Material& m) {
    std::vector<MapUse> maps;
    if (!m.keptSurface) return maps;
    if (m.baseColorTexture && (m.keptSurface->print || m.alphaMode != AlphaMode::Opaque))
        maps.push_back({"MAP_BASE_COLOR", &m.baseColorTexture});
    if (m.normalTexture) maps.push_back({"MAP_NORMAL", &m.normalTexture});
    return maps;
}

void setNearest(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
}

}  // namespace

std::string wovenParamsGlslStruct() {
    std::ostringstream s;
    s << "struct WovenParams {\n";
    for (const ParamInfo& info : wovenParamTable())
        if (isNumeric(info.type)) s << "    " << glslType(info.type) << " " << info.name << ";\n";
    s << "};\n";
    return s.str();
}

bool yarnsTransmit(const WovenParams& p) {
    const std::vector<Yarn> yarns = Weave::resolvedYarns(p);
    return std::any_of(yarns.begin(), yarns.end(), [](const Yarn& y) { return y.transmission() > 0.0f; });
}

std::string wovenFeatureDefines(const WovenParams& p, bool filterWeave) {
    std::string d;
    if (hasNoise(p)) d += "#define WOVEN_NOISE\n";
    if (p.crimp > 0.0f) d += "#define WOVEN_CRIMP\n";
    if (mayShowGaps(p)) d += "#define WOVEN_GAPS\n";
    if (hasThreadLists(p)) d += "#define WOVEN_THREADS\n";
    if (!p.warp_spacing.empty() || !p.weft_spacing.empty()) d += "#define WOVEN_SPACING\n";
    if (yarnsTransmit(p)) d += "#define WOVEN_TRANSMISSION\n";
    // The far field's cross-section count is core's (weave_far_field.h), so both average alike.
    if (filterWeave) d += "#define WOVEN_FILTER\n#define FILTER_SAMPLES " + std::to_string(kFarFieldSections) + "\n";
    return d;
}

void uploadWovenParams(const ShaderProgram& program, const WovenParams& p) {
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) continue;
        const GLint location = program.uniform((std::string("material.") + info.name).c_str());
        if (location < 0) continue;  // compiled out for this material
        const char* base = reinterpret_cast<const char*>(&p) + info.offset;
        const float* f = reinterpret_cast<const float*>(base);
        const int* i = reinterpret_cast<const int*>(base);
        switch (info.type) {
            case ParamType::Float: glUniform1f(location, *f); break;
            case ParamType::Int: glUniform1i(location, *i); break;
            case ParamType::Vec2: glUniform2fv(location, 1, f); break;
            case ParamType::Vec3: glUniform3fv(location, 1, f); break;
            case ParamType::IVec3: glUniform3iv(location, 1, i); break;
            default: break;
        }
    }
}

WeaveTextures::WeaveTextures() {
    glGenTextures(1, &tile_);
    glGenTextures(1, &floats_);
    glGenTextures(1, &threadTable_);
    glGenTextures(1, &yarnTable_);
    glGenTextures(2, colorTracks_);
    glGenBuffers(1, &threadBuffer_);
    glGenBuffers(1, &yarnBuffer_);
    glGenTextures(1, &warpTopSums_);
    glGenTextures(1, &colorTopSums_);
}

WeaveTextures::~WeaveTextures() {
    const GLuint textures[] = {tile_,           floats_,      threadTable_, yarnTable_, colorTracks_[0],
                               colorTracks_[1], warpTopSums_, colorTopSums_};
    glDeleteTextures(8, textures);
    const GLuint buffers[] = {threadBuffer_, yarnBuffer_};
    glDeleteBuffers(2, buffers);
}

void WeaveTextures::update(const WovenParams& p) {
    if (!uploaded_ || !sameThreads(*uploaded_, p)) {
        const Weave weave(p);
        if (!uploaded_ || !sameTile(*uploaded_, p)) updateTile(weave);
        updateThreads(weave);
        coverage_[0] = weaveCoverage(weave, false);
        coverage_[1] = weaveCoverage(weave, true);
        updateFootprintSplit(weave, p);
    }
    // The yarn table: the resolved yarns, which every yarn slider changes; a few floats each.
    std::vector<glm::vec4> yarns;
    for (const Yarn& y : Weave::resolvedYarns(p)) {
        yarns.emplace_back(y.ex(), y.ey(), y.rs(), y.width());
        yarns.emplace_back(y.cy(), y.noise(), y.transmission(), y.transmissionGloss());
    }
    uploadBuffer(yarnBuffer_, yarnTable_, yarns);
    uploaded_ = p;
}

void WeaveTextures::updateTile(const Weave& weave) {
    // The front face's bit per cell (the back inverts it in the shader), one byte a texel.
    const WeavePattern& front = weave.pattern(false);
    const int w = front.width(), h = front.height();
    std::vector<uint8_t> warp(size_t(w) * size_t(h));
    for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) warp[size_t(v) * size_t(w) + size_t(u)] = front.topInTile(u, v) == YarnType::Warp;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, tile_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, w, h, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, warp.data());
    setNearest(GL_TEXTURE_2D);
    if (const WeaveFloats* floats = weave.floats()) {
        glBindTexture(GL_TEXTURE_2D, floats_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16UI, w, h, 0, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, floats->runs().data());
        setNearest(GL_TEXTURE_2D);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void WeaveTextures::updateThreads(const Weave& weave) {
    // Per slot, warp ends then weft picks: (colour, yarn), (cell start, cell width, the slot the
    // unit interval from the slot's index starts in), as ThreadLayout keeps them.
    std::vector<glm::vec4> texels;
    const ThreadLayout* sides[] = {&weave.warp(), &weave.weft()};
    for (int s = 0; s < 2; ++s) {
        const ThreadLayout& side = *sides[s];
        for (int k = 0; k < side.period(); ++k) {
            texels.emplace_back(side.color(k), float(side.yarn(k)));
            texels.push_back(side.spaced() ? glm::vec4(float(side.start(k)), float(side.width(k)),
                                                       float(side.firstInInterval(k)), 0.0f)
                                           : glm::vec4(float(k), 1.0f, float(k), 0.0f));
        }
        threadPeriod_[s] = side.period();
        threadSpaced_[s] = side.spaced() ? 1 : 0;
        uploadColorTrack(colorTracks_[s], side);
    }
    uploadBuffer(threadBuffer_, threadTable_, texels);
}

void WeaveTextures::updateFootprintSplit(const Weave& weave, const WovenParams& p) {
    // A float table counts cells exactly up to 2^24; larger tiles are left unsplit (the repeat's
    // shares at every footprint, as for unevenly spaced threads).
    constexpr size_t kMaxTableTexels = size_t(1) << 22;
    auto fits = [&](glm::ivec2 size) { return size_t(size.x + 1) * size_t(size.y + 1) <= kMaxTableTexels; };
    colorTableSizes_ = glm::ivec4(0);
    for (int face = 0; face < 2; ++face) {
        const WeaveFarField far(weave, p, face == 1);
        splitsByFootprint_[face] = far.splitsByFootprint() && fits(far.tileSize());
        farShares_[face] = far.colorShares();
        inWarpCells_[face] = far.sharesInWarpCells();
        inWeftCells_[face] = far.sharesInWeftCells();
        // The front face's tables; the shader turns them into the back's (whose warp-top cells are
        // the front's others).
        if (face == 1 || !splitsByFootprint_[face]) continue;
        const glm::ivec2 tile = far.tileSize();
        glBindTexture(GL_TEXTURE_2D, warpTopSums_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, tile.x + 1, tile.y + 1, 0, GL_RED, GL_FLOAT, far.warpTopSums().data());
        setNearest(GL_TEXTURE_2D);
        // The warp's colour table at the top left, the weft's below it.
        const glm::ivec2 warp = far.weightsColors(0) && fits(far.colorTableSize(0)) ? far.colorTableSize(0) : glm::ivec2(0);
        const glm::ivec2 weft = far.weightsColors(1) && fits(far.colorTableSize(1)) ? far.colorTableSize(1) : glm::ivec2(0);
        colorTableSizes_ = glm::ivec4(warp, weft);
        if (warp.x == 0 && weft.x == 0) continue;
        const int width = std::max(warp.x, weft.x) + 1, weftRow = warp.y + 1;
        std::vector<glm::vec4> texels(size_t(width) * size_t(weftRow + weft.y + 1), glm::vec4(0.0f));
        for (int side = 0; side < 2; ++side) {
            const glm::ivec2 size = side == 0 ? warp : weft;
            if (size.x == 0) continue;
            const std::vector<glm::vec4>& sums = far.colorTopSums(side);
            for (int v = 0; v <= size.y; ++v)
                std::copy_n(sums.begin() + ptrdiff_t(v) * (size.x + 1), size.x + 1,
                            texels.begin() + ptrdiff_t(v + (side == 0 ? 0 : weftRow)) * width);
        }
        glBindTexture(GL_TEXTURE_2D, colorTopSums_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, weftRow + weft.y + 1, 0, GL_RGBA, GL_FLOAT, texels.data());
        setNearest(GL_TEXTURE_2D);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
}

void WeaveTextures::bind(const ShaderProgram& program) const {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tile_);
    glUniform1i(program.uniform("weaveTile"), 0);
    const GLint floats = program.uniform("weaveFloats");
    if (floats >= 0) {
        glActiveTexture(GL_TEXTURE3);
        glBindTexture(GL_TEXTURE_2D, floats_);
        glUniform1i(floats, 3);
    }
    const GLint threads = program.uniform("threadTable");
    if (threads >= 0) {
        glActiveTexture(GL_TEXTURE4);
        glBindTexture(GL_TEXTURE_BUFFER, threadTable_);
        glUniform1i(threads, 4);
        glActiveTexture(GL_TEXTURE5);
        glBindTexture(GL_TEXTURE_BUFFER, yarnTable_);
        glUniform1i(program.uniform("yarnTable"), 5);
        glUniform2iv(program.uniform("threadPeriod"), 1, glm::value_ptr(threadPeriod_));
        glUniform2iv(program.uniform("threadSpaced"), 1, glm::value_ptr(threadSpaced_));
    }
    const GLint warpColors = program.uniform("warpColorTexture");
    if (warpColors >= 0) {
        glActiveTexture(GL_TEXTURE6);
        glBindTexture(GL_TEXTURE_1D, colorTracks_[0]);
        glUniform1i(warpColors, 6);
        glActiveTexture(GL_TEXTURE7);
        glBindTexture(GL_TEXTURE_1D, colorTracks_[1]);
        glUniform1i(program.uniform("weftColorTexture"), 7);
    }
    if (program.uniform("splitsByFootprint[0]") >= 0) {
        glActiveTexture(GL_TEXTURE14);
        glBindTexture(GL_TEXTURE_2D, warpTopSums_);
        glUniform1i(program.uniform("warpTopSums"), 14);
        const GLint split[2] = {splitsByFootprint_[0], splitsByFootprint_[1]};
        glUniform1iv(program.uniform("splitsByFootprint[0]"), 2, split);
        glUniform3fv(program.uniform("farShares[0]"), 2, glm::value_ptr(farShares_[0]));
        glUniform3fv(program.uniform("inWarpCells[0]"), 2, glm::value_ptr(inWarpCells_[0]));
        glUniform3fv(program.uniform("inWeftCells[0]"), 2, glm::value_ptr(inWeftCells_[0]));
    }
    const GLint colorTables = program.uniform("colorTableSizes");
    if (colorTables >= 0) {
        glActiveTexture(GL_TEXTURE15);
        glBindTexture(GL_TEXTURE_2D, colorTopSums_);
        glUniform1i(program.uniform("colorTopSums"), 15);
        glUniform4iv(colorTables, 1, glm::value_ptr(colorTableSizes_));
    }
    const glm::vec4 coverage(coverage_[0].weft, coverage_[0].warp, coverage_[1].weft, coverage_[1].warp);
    glUniform4fv(program.uniform("yarnCoverage"), 1, glm::value_ptr(coverage));
    glActiveTexture(GL_TEXTURE0);
}

void uploadKeptSurface(const ShaderProgram& program, const Material& m, GpuTextures& textures, int firstUnit) {
    glUniform4fv(program.uniform("baseColorFactor"), 1, glm::value_ptr(m.baseColor));
    glUniform1f(program.uniform("alphaCutoff"), m.alphaCutoff);
    glUniform1f(program.uniform("normalScale"), m.normalTexture.scale);
    textures.bindMaps(program, keptSurfaceMaps(m), firstUnit);
}

std::string wovenProgramPreamble(const Material& material, bool filterWeave, ShadowLookups shadows) {
    std::string defines = wovenFeatureDefines(*material.woven, filterWeave) + mapDefines(keptSurfaceMaps(material));
    if (material.keptSurface) {
        if (material.keptSurface->print) defines += "#define WOVEN_PRINT\n";
        defines += alphaDefines(material);
    }
    return defines + shadowLookupDefines(shadows) + wovenParamsGlslStruct();
}

std::unique_ptr<ShaderProgram> buildWovenProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"mesh_varyings.glsl", "frame.glsl", "woven_params.glsl", "ashikhmin_shirley.glsl",
                                 "yarn_noise.glsl", "yarn_geometry.glsl", "woven_transmission.glsl", "lighting.glsl",
                                 "screen_door.glsl", "texture_maps.glsl", "normal_map.glsl", "woven.frag"},
        preamble);
}

std::unique_ptr<ShaderProgram> buildWovenShadowProgram(const std::string& preamble) {
    return std::make_unique<ShaderProgram>(
        std::vector<std::string>{"mesh.vert"},
        std::vector<std::string>{"mesh_varyings.glsl", "frame.glsl", "woven_params.glsl", "ashikhmin_shirley.glsl",
                                 "yarn_geometry.glsl", "woven_transmission.glsl", "shadow_depth.glsl", "woven_shadow.frag"},
        preamble);
}

}  // namespace woven
