#pragma once
// A woven material baked to a standard glTF 2.0 material (docs/EXPORT.md): the textures of one
// repeat of its weave (or of several), which any glTF renderer shows without woven's model.
//   base colour          per-thread colours and noise, alpha = the see-through part (MASK)
//   normal               the yarns' bump and crimp, tangent space
//   metallic-roughness   G: roughness across the fitted lobe; metallic 0
//   anisotropy           KHR_materials_anisotropy: RG direction, B strength, along the top yarn
//   diffuse transmission KHR_materials_diffuse_transmission's colour texture, where the yarns
//                        transmit: each texel's body transmittance over the material's factor
// plus the factors fitted to the model's far field (far_field_fit.h: a base colour scale,
// KHR_materials_specular, KHR_materials_sheen) and KHR_materials_ior from rs. Every
// texel is fitted from the model over its footprint (texel_fit.h), and so is every mip level:
// the levels of a texture are averaged in the model, not in texel space.
#include <functional>
#include <string>
#include <vector>

#include "scene_description.h"
#include "woven_params.h"

namespace woven {

struct BakeOptions {
    int size = 512;        // texels along the longer side of the texture
    int repeats = 1;       // weave repeats the texture holds along u and along v
    int supersamples = 4;  // model points per texel side
    bool sheen = true;     // fit KHR_materials_sheen to the far field (else none)
    // KHR_materials_anisotropy; without it one roughness a texel (texel_fit.h's isotropic()), for
    // renderers that ignore the extension and would show the smoother width alone.
    bool anisotropy = true;
    // Called with the fraction of texels sampled so far (0 to 1), one call at a time: a bake of
    // 8192^2 texels takes minutes.
    std::function<void(double)> progress;
};

// What a bake holds per level-0 texel at its peak, rounded up: the model's sums (104 bytes), the
// fits of every level (76), one level's sums being downsampled (26), the encoded maps of every
// level (22) and their PNG or glTF copies on writing (32), with room to spare. A bake larger than
// the machine's memory is refused before anything is allocated.
constexpr size_t kBakeBytesPerTexel = 320;

struct BakedMaterial {
    // The glTF material; its textures index `textures`, with KHR_texture_transform's scale set so
    // one texture spans `uvSize` of the mesh's texture coordinates: the weave keeps its size.
    Material material;
    // Base colour, normal, metallic-roughness, anisotropy (kBaseColor...), and the diffuse
    // transmission's colour where the yarns transmit: level 0.
    std::vector<TextureImage> textures;
    enum Map { kBaseColor, kNormal, kMetallicRoughness, kAnisotropy, kDiffuseTransmission };
    static constexpr int kMapCount = 4;  // the maps of every bake, before kDiffuseTransmission
    static const char* mapName(int map);  // "base_color", "normal", ...
    // Levels 1, 2, ... of each texture, fitted from the model, down to 1 x 1.
    std::vector<std::vector<TextureImage>> mipLevels;
    glm::ivec2 threads{1};    // ends x picks of one weave repeat
    glm::dvec2 uvSize{1.0};   // the texture's extent in the mesh's uv
    double farFieldError = 0.0;  // relative RMSE of the far field against the model's (far_field.h)
    // What glTF cannot say and the bake approximated, one line each (also for the user).
    std::vector<std::string> notes;
};

// Throws std::invalid_argument for invalid parameters or options, a repeat too long to bake at
// `size` (fewer than 4 texels a thread), or a bake whose estimate exceeds physical memory.
BakedMaterial bakeWoven(const WovenParams& params, const BakeOptions& options = {});

// `baked` standing in for the woven material `original` of a scene: the baked glTF material with
// the original's name, emission and sides, its textures at scene.textures[firstTexture...].
Material bakedMaterial(const Material& original, const BakedMaterial& baked, int firstTexture);

}  // namespace woven
