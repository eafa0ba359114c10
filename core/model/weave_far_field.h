#pragma once
// The far field of a weave (MODEL.md section 7): what a footprint covering many weave elements
// sees, as one mixture of Ashikhmin-Shirley lobes. Each yarn that shows on a face enters with the
// share of the surface it covers (weaveCoverage()), its cross-section sampled at
// kFarFieldSections evenly spaced across positions (each a lobe around its bumped normal); where
// gaps show a backing, the backing enters with the gap's share. See-through gaps are no lobe: rays
// pass them by their exact uv, so the far field is what the opaque part shows (the shares are
// normalised over it). Crimp and colour noise average out along a yarn and are left out. This is
// the one definition of the far field: the renderer's filtered BSDF (FilteredWeaveLobe) and the
// preview's shaders/woven.frag (averagedRadiance, from the same shares and constants) both
// evaluate it.
#include <vector>

#include "ashikhmin_shirley.h"
#include "frame.h"
#include "weave.h"

namespace woven {

// Across positions per yarn: x_k = (k + 1/2) 2 / kFarFieldSections - 1 (the GLSL's FILTER_SAMPLES).
constexpr int kFarFieldSections = 8;
inline float farFieldSection(int k) { return (float(k) + 0.5f) * (2.0f / float(kFarFieldSections)) - 1.0f; }

// The far field's share of the blend for a footprint `elements` weave elements wide (the larger
// of its widths along u and v, each |de/dx| + |de/dy|, as GLSL's fwidth): 0 below a quarter
// element, 1 from one element on, smoothstep between (woven.frag's farWeight).
float farFieldWeight(float elements);

// Which colour a far-field lobe takes at a point: the warp's or the weft's mean over the
// footprint, or the backing colour.
enum class FarFieldColor { Warp = 0, Weft = 1, Backing = 2 };

struct FarFieldLobe {
    Frame frame;  // in the tangent frame (x = +u, y = +v, z = the surface normal)
    LobeShape shape;
    // The probability sample() picks its specular part: the lobe's default for the material's own
    // colour of its side (any fixed choice keeps sample() and pdf() consistent).
    float specularProbability;
    float weight;  // its share of the far field; the shares sum to 1
    FarFieldColor color;
};

class WeaveFarField {
public:
    // `weave` built from `p`; `backSide`: the back face, where the other yarn is on top.
    WeaveFarField(const Weave& weave, const WovenParams& p, bool backSide);

    // Lobes of the same frame, shape and colour are merged (a flat yarn's sections are one lobe).
    // Their weights are the shares of one whole repeat of the weave.
    const std::vector<FarFieldLobe>& lobes() const { return lobes_; }

    // What a footprint smaller than the repeat sees: the box [e0, e1] (weave elements, e = uv x
    // repeat) covers more or fewer cells with the warp on top than the repeat does (a satin's
    // warp dots, a twill's diagonals). Returns the factor for each colour's lobes (FarFieldColor
    // order) that turns the repeat's shares into the box's, the shares still summing to 1; each
    // side's yarns keep their proportions. 1 for a footprint of whole repeats, and always for
    // unevenly spaced threads (whose cells are not the tile's unit cells).
    glm::vec3 footprintScales(const glm::dvec2& e0, const glm::dvec2& e1) const;

    // What a footprint smaller than the repeat sees of each side's colours: where threads of
    // different colours cross (a houndstooth's blocks, a gingham's checks) the warp shows its own
    // colour only in the cells where it shows at all, mostly those with the warp on top. Given the
    // plain means of the warp's and the weft's colours over the box [e0, e1] (ThreadLayout::
    // meanColor()), returns them weighted by each cell's share of that side's yarn. Unchanged where
    // the side has one colour, where footprintScales() does not split, and for footprints of
    // whole repeats of the tile and the colours (to which the weighting tends).
    void footprintColors(const glm::dvec2& e0, const glm::dvec2& e1, glm::vec3& warp, glm::vec3& weft) const;

    // What footprintScales() is computed from, for its GLSL twin (woven.frag): whether it splits
    // by top yarn at all, each colour's share of the repeat and of the cells with the warp on top
    // and of the others, and the (width + 1) x (height + 1) table of warp-top cells below and
    // left of each corner of the tile.
    bool splitsByFootprint() const { return byFootprint_; }
    glm::vec3 colorShares() const { return {share_[0], share_[1], share_[2]}; }
    glm::vec3 sharesInWarpCells() const { return {inWarpCells_[0], inWarpCells_[1], inWarpCells_[2]}; }
    glm::vec3 sharesInWeftCells() const { return {inWeftCells_[0], inWeftCells_[1], inWeftCells_[2]}; }
    glm::ivec2 tileSize() const { return {tileWidth_, tileHeight_}; }
    const std::vector<float>& warpTopSums() const { return warpTopSums_; }
    // What footprintColors() is computed from, per side (0 the warp, 1 the weft): whether it
    // weights that side's colours, the size of its table (the joint period of the tile and the
    // side's colours along its threads' axis, the tile's along the other) and the table of
    // (warp-top cells x the side's colour, warp-top cells) below and left of each corner, (width
    // + 1) x (height + 1).
    bool weightsColors(int side) const { return !colorTops_[side].empty(); }
    glm::ivec2 colorTableSize(int side) const { return colorTableSize_[side]; }
    const std::vector<glm::vec4>& colorTopSums(int side) const { return colorTops_[side]; }

private:

    std::vector<FarFieldLobe> lobes_;
    int tileWidth_ = 1, tileHeight_ = 1;
    std::vector<float> warpTopSums_;  // (width + 1) x (height + 1): warp-top cells below and left of each corner
    std::vector<glm::vec4> colorTops_[2];  // warp, weft: footprintColors()'s tables, empty where unused
    glm::ivec2 colorTableSize_[2] = {glm::ivec2(0), glm::ivec2(0)};
    bool byFootprint_ = false;
    // Per colour: its share of the repeat, and its share of the cells with the warp on top and of
    // the others (as fractions of those cells' area).
    float share_[3] = {0, 0, 0}, inWarpCells_[3] = {0, 0, 0}, inWeftCells_[3] = {0, 0, 0};
    float warpCells_ = 0.0f;
};

}  // namespace woven
