#include "woven_bake.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "lobe_fit.h"
#include "far_field_fit.h"
#include "srgb.h"
#include "system_memory.h"
#include "texel_fit.h"
#include "weave.h"

namespace woven {

namespace {

// The weave's repeat in threads: the tile and the threads' period (colours, yarns, spacing)
// together. Noise never repeats; the bake takes the first repeat's.
glm::ivec2 repeatThreads(const WovenMaterial& model) {
    const Weave& weave = model.weave();
    const long ends = std::lcm(long(weave.pattern(false).width()), long(weave.warp().period()));
    const long picks = std::lcm(long(weave.pattern(false).height()), long(weave.weft().period()));
    if (ends > kMaxTileSide || picks > kMaxTileSide)
        throw std::invalid_argument("the weave repeats only every " + std::to_string(ends) + " x " + std::to_string(picks) +
                                    " threads (its tile and its thread lists together), too many to bake");
    return {int(ends), int(picks)};
}

void checkBakeFitsInMemory(glm::ivec2 size) {
    const size_t memory = physicalMemoryBytes();
    const double needed = double(size.x) * double(size.y) * double(kBakeBytesPerTexel);
    if (memory > 0 && needed > double(memory))
        throw std::invalid_argument("a " + std::to_string(size.x) + " x " + std::to_string(size.y) + " bake needs about " +
                                    gibibytes(needed) + " of memory (" + std::to_string(kBakeBytesPerTexel) +
                                    " bytes per texel), more than this machine's " + gibibytes(double(memory)) +
                                    ": bake it smaller (--size)");
}

// Level-0 sums of a W x H texture over `extent` threads (uv = thread coordinate / repeat).
std::vector<TexelSums> sampleTexels(const WovenMaterial& model, glm::ivec2 size, glm::dvec2 extent, int n,
                                    const std::function<void(double)>& progress) {
    std::vector<TexelSums> sums(size_t(size.x) * size_t(size.y));
    const glm::dvec2 repeat(model.params().repeat);
    std::atomic<int> rowsDone{0};
    std::mutex reporting;
    tbb::parallel_for(tbb::blocked_range<int>(0, size.y), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = 0; x < size.x; ++x) {
                TexelSums& s = sums[size_t(y) * size.x + x];
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        ShadingInput in;
                        const glm::dvec2 texel((x + (i + 0.5) / n) / size.x, (y + (j + 0.5) / n) / size.y);
                        in.uv = texel * extent / repeat;
                        s.add(model.shade(in));
                    }
            }
            const int done = ++rowsDone;
            if (progress && reporting.try_lock()) {
                progress(double(done) / size.y);
                reporting.unlock();
            }
        }
    });
    return sums;
}

// The sums of level `level`'s texels (each the block of level-0 texels it covers).
std::vector<TexelSums> downsample(const std::vector<TexelSums>& base, glm::ivec2 size, glm::ivec2 levelSize) {
    std::vector<TexelSums> sums(size_t(levelSize.x) * size_t(levelSize.y));
    for (int y = 0; y < size.y; ++y) {
        const int ly = int(int64_t(y) * levelSize.y / size.y);
        for (int x = 0; x < size.x; ++x) sums[size_t(ly) * levelSize.x + size_t(int64_t(x) * levelSize.x / size.x)] += base[size_t(y) * size.x + x];
    }
    return sums;
}

// Fits, with the texels that see only gaps taking their covered neighbours' fit (repeatedly,
// across the texture's wrap), so that filtering at a yarn's edge does not blend in a gap's
// meaningless colour, normal or roughness. Their coverage stays 0.
std::vector<TexelFit> fitAll(const std::vector<TexelSums>& sums, glm::ivec2 size) {
    std::vector<TexelFit> fits(sums.size());
    std::vector<char> known(sums.size());
    for (size_t i = 0; i < sums.size(); ++i) {
        fits[i] = fitTexel(sums[i]);
        known[i] = sums[i].covered > 0.0;
    }
    for (int pass = 0; pass < size.x + size.y; ++pass) {
        std::vector<size_t> filled;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const size_t i = size_t(y) * size.x + x;
                if (known[i]) continue;
                TexelSums neighbours;
                const glm::ivec2 offsets[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
                for (const glm::ivec2& o : offsets) {
                    const size_t j = size_t((y + o.y + size.y) % size.y) * size.x + size_t((x + o.x + size.x) % size.x);
                    if (known[j]) neighbours += sums[j];
                }
                if (neighbours.covered > 0.0) {
                    const TexelFit fit = fitTexel(neighbours);
                    fits[i] = fit;
                    fits[i].coverage = 0.0f;
                    filled.push_back(i);
                }
            }
        if (filled.empty()) break;
        for (size_t i : filled) known[i] = 1;
    }
    return fits;
}

uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }
uint8_t signed8(float v) { return unorm8(0.5f * (v + 1.0f)); }

// `colorScale` multiplies the base colour (the far field's fitted scale); a `transmission` above
// 0 (the diffuse transmission's factor) adds the transmission's colour map, T over it.
std::vector<TextureImage> encode(const std::vector<TexelFit>& fits, glm::ivec2 size, int level, float colorScale,
                                 float transmission) {
    std::vector<TextureImage> maps(BakedMaterial::kMapCount + (transmission > 0.0f ? 1 : 0));
    for (int m = 0; m < int(maps.size()); ++m) {
        maps[size_t(m)].name = std::string("baked ") + BakedMaterial::mapName(m) + (level ? " level " + std::to_string(level) : "");
        maps[size_t(m)].width = size.x;
        maps[size_t(m)].height = size.y;
        maps[size_t(m)].bytes.reserve(fits.size());
    }
    for (const TexelFit& t : fits) {
        const glm::vec3 c = glm::clamp(colorScale * t.baseColor, 0.0f, 1.0f);
        maps[BakedMaterial::kBaseColor].bytes.emplace_back(unorm8(linearToSrgb(c.r)), unorm8(linearToSrgb(c.g)), unorm8(linearToSrgb(c.b)),
                                                           unorm8(t.coverage));
        maps[BakedMaterial::kNormal].bytes.emplace_back(signed8(t.normal.x), signed8(t.normal.y), signed8(t.normal.z), 255);
        // R is occlusion's channel in an ORM texture: 1, nothing occluded.
        maps[BakedMaterial::kMetallicRoughness].bytes.emplace_back(255, unorm8(t.roughness), 0, 255);
        maps[BakedMaterial::kAnisotropy].bytes.emplace_back(signed8(t.direction.x), signed8(t.direction.y), unorm8(t.anisotropy), 255);
        if (transmission > 0.0f) {
            const glm::vec3 c = glm::clamp(t.transmitted / transmission, 0.0f, 1.0f);
            maps[BakedMaterial::kDiffuseTransmission].bytes.emplace_back(unorm8(linearToSrgb(c.r)), unorm8(linearToSrgb(c.g)),
                                                                         unorm8(linearToSrgb(c.b)), 255);
        }
    }
    return maps;
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s.precision(digits);
    s << std::fixed << v;
    return s.str();
}

}  // namespace

const char* BakedMaterial::mapName(int map) {
    static const char* const names[] = {"base_color", "normal", "metallic_roughness", "anisotropy", "diffuse_transmission"};
    return names[map];
}

namespace {

// What the texels say of the whole bake: whether any has gaps, the range of the yarns' specular
// reflectance rs, and the most light any texel's yarns pass in a channel (at most 1).
struct TexelSummary {
    bool gaps = false;
    double rsMin = 1.0, rsMax = 0.0, transmission = 0.0;
};

TexelSummary summarise(const std::vector<TexelSums>& sums) {
    TexelSummary t;
    for (const TexelSums& s : sums) {
        t.gaps = t.gaps || s.covered < s.points;
        if (s.covered > 0.0) t.rsMin = std::min(t.rsMin, s.rs / s.covered), t.rsMax = std::max(t.rsMax, s.rs / s.covered);
        if (s.covered > 0.0)
            t.transmission =
                std::max({t.transmission, s.transmitted.r / s.covered, s.transmitted.g / s.covered, s.transmitted.b / s.covered});
    }
    t.transmission = std::min(t.transmission, 1.0);
    return t;
}

// The texels' fits at every mip level, level 0 of `size` down to one texel, each level fitted in
// the model from the texel sums averaged down (not from the level above's fits); `sizes` gets
// each level's size.
std::vector<std::vector<TexelFit>> fitMipLevels(const std::vector<TexelSums>& sums, const glm::ivec2& size, bool anisotropy,
                                                std::vector<glm::ivec2>& sizes) {
    std::vector<std::vector<TexelFit>> levels{fitAll(sums, size)};
    sizes = {size};
    for (int level = 1; size.x >> (level - 1) > 1 || size.y >> (level - 1) > 1; ++level) {
        sizes.emplace_back(std::max(1, size.x >> level), std::max(1, size.y >> level));
        levels.push_back(fitAll(downsample(sums, size, sizes.back()), sizes.back()));
    }
    if (!anisotropy)
        for (std::vector<TexelFit>& level : levels)
            for (TexelFit& t : level) t = isotropic(t);
    return levels;
}

// A texture over one tile of the bake, `uvSize` in the mesh's uv, repeated across it.
TextureRef tileTexture(const glm::dvec2& uvSize) {
    TextureRef ref;
    ref.uvTransform = glm::mat3(float(1.0 / uvSize.x), 0, 0, 0, float(1.0 / uvSize.y), 0, 0, 0, 1);
    return ref;
}

// The material's maps that the texels decide (base colour, normal, metallic-roughness and, when
// anisotropic, the anisotropy), each `ref` with its image, and the factors they scale.
void setTexelMaps(Material& m, const TextureRef& ref, bool anisotropy) {
    m.baseColor = glm::vec4(1.0f);
    m.baseColorTexture = ref;
    m.baseColorTexture.image = BakedMaterial::kBaseColor;
    m.baseColorTexture.srgb = true;
    m.normalTexture = ref;
    m.normalTexture.image = BakedMaterial::kNormal;
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.metallicRoughnessTexture = ref;
    m.metallicRoughnessTexture.image = BakedMaterial::kMetallicRoughness;
    if (anisotropy) {
        m.anisotropy.strength = 1.0f;
        m.anisotropy.texture = ref;
        m.anisotropy.texture.image = BakedMaterial::kAnisotropy;
    }
}

}  // namespace

BakedMaterial bakeWoven(const WovenParams& params, const BakeOptions& o) {
    if (o.size < 1 || o.size > kMaxTileSide) throw std::invalid_argument("the bake size must be from 1 to " + std::to_string(kMaxTileSide));
    if (o.repeats < 1 || o.repeats > 1024) throw std::invalid_argument("the repeats must be from 1 to 1024");
    if (o.supersamples < 1 || o.supersamples > 16) throw std::invalid_argument("the supersamples must be from 1 to 16");
    const WovenMaterial model(params);
    BakedMaterial baked;
    baked.threads = repeatThreads(model);
    // Square threads: the longer side of the texture gets `size` texels.
    const glm::dvec2 extent = glm::dvec2(baked.threads) * double(o.repeats);
    const double texelsPerThread = o.size / std::max(extent.x, extent.y);
    const glm::ivec2 size(std::max(1L, std::lround(extent.x * texelsPerThread)), std::max(1L, std::lround(extent.y * texelsPerThread)));
    if (texelsPerThread < 4.0)
        throw std::invalid_argument("the weave repeats every " + std::to_string(baked.threads.x) + " x " +
                                    std::to_string(baked.threads.y) + " threads: at " + std::to_string(o.size) +
                                    " texels that is " + fixed(texelsPerThread, 1) +
                                    " a thread, too few for its yarns (at least 4); bake it larger (--size)");
    baked.uvSize = extent / glm::dvec2(params.repeat);
    checkBakeFitsInMemory(size);

    const std::vector<TexelSums> sums = sampleTexels(model, size, extent, o.supersamples, o.progress);
    const TexelSummary texels = summarise(sums);
    const double rsMin = texels.rsMin, rsMax = texels.rsMax, transmission = texels.transmission;
    std::vector<glm::ivec2> levelSizes;
    const std::vector<std::vector<TexelFit>> levels = fitMipLevels(sums, size, o.anisotropy, levelSizes);
    baked.textures = encode(levels[0], size, 0, 1.0f, float(transmission));

    const TextureRef ref = tileTexture(baked.uvSize);
    Material& m = baked.material;
    setTexelMaps(m, ref, o.anisotropy);
    m.alphaMode = texels.gaps ? AlphaMode::Mask : AlphaMode::Opaque;
    m.alphaCutoff = 0.5f;
    const double rs = rsMax >= rsMin ? 0.5 * (rsMin + rsMax) : params.rs;
    m.ior = iorForF0(float(rs));
    if (rsMax - rsMin > 1e-3)
        baked.notes.push_back("its yarns' specular reflectance rs differs (" + fixed(rsMin, 3) + " to " + fixed(rsMax, 3) +
                              "): the baked material has one IOR, for rs " + fixed(rs, 3));
    if (hasNoise(params))
        baked.notes.push_back("its colour noise never repeats: the bake holds the first " +
                              std::to_string(o.repeats) + " repeat(s) of it, tiled");
    // The yarns' transmission (docs/MODEL_TRANSMISSION.md) as KHR_materials_diffuse_transmission:
    // the light glTF's diffuse base passes, (1 - F) D colour, is the model's T (1 - R_s) at normal
    // incidence, per texel the mean over its covered points (the gaps stay alpha; a gap's texel
    // takes its neighbours' T, as its other maps do). D is the largest channel of any texel's T,
    // so the colour texture holds T / D, at most 1; the far field's base scale below then takes up
    // what the diffuse reflection loses. Opaque yarns write no extension and no map.
    if (transmission > 0.0) {
        m.diffuseTransmission.factor = float(transmission);
        m.diffuseTransmission.colorTexture = ref;
        m.diffuseTransmission.colorTexture.image = BakedMaterial::kDiffuseTransmission;
        m.diffuseTransmission.colorTexture.srgb = true;
        baked.notes.push_back("its yarns' transmission is baked as KHR_materials_diffuse_transmission (its colour a texture "
                              "per texel), all of it diffuse: glTF has no forward (transmission_gloss) lobe");
    }
    // The factors no texel decides, from the far field; the base colour's scale goes into the textures.
    const FarFieldFit fit = fitFarField(params, m, baked.textures, baked.uvSize, o.sheen);
    m.specular = fit.specular;
    m.sheen = fit.sheen;
    baked.farFieldError = fit.after;
    baked.textures = encode(levels[0], size, 0, fit.baseScale, float(transmission));
    baked.mipLevels.assign(baked.textures.size(), {});
    for (size_t level = 1; level < levels.size(); ++level) {
        const std::vector<TextureImage> maps = encode(levels[level], levelSizes[level], int(level), fit.baseScale, float(transmission));
        for (size_t map = 0; map < maps.size(); ++map) baked.mipLevels[map].push_back(maps[map]);
    }
    return baked;
}

Material bakedMaterial(const Material& original, const BakedMaterial& baked, int firstTexture) {
    Material m = baked.material;
    m.name = original.name;
    m.draft = original.draft;
    m.emission = original.emission;
    m.emissiveTexture = original.emissiveTexture;
    m.doubleSided = original.doubleSided;
    for (TextureRef* ref : {&m.baseColorTexture, &m.normalTexture, &m.metallicRoughnessTexture, &m.anisotropy.texture,
                            &m.diffuseTransmission.colorTexture})
        if (*ref) ref->image += firstTexture;
    return m;
}

}  // namespace woven
