// The material of the mesh being drawn. `struct WovenParams` itself is not written here: the
// C++ side generates it from core's wovenParamTable() (app/preview/woven_gl_material.cpp), one
// field per numeric table entry with the same name, and uploads every field by that name. A
// table entry the shaders never read shows up as an inactive uniform, which tests/preview checks.
uniform WovenParams material;

// The weave tile, texel (U mod P_u, V mod P_v): 1 where the warp is on top of the front face
// (the back face inverts it).
uniform usampler2D weaveTile;
#ifdef WOVEN_CRIMP
// The float through each cell along its row and along its column (core's WeaveFloats::runs()):
// row position, row length - 1, column position, column length - 1.
uniform usampler2D weaveFloats;
#endif
#ifdef WOVEN_THREADS
// Per thread slot, warp ends then weft picks (core's ThreadLayout): (colour, yarn),
// (cell start, cell width, the slot the unit interval from the slot's index starts in).
uniform samplerBuffer threadTable;
// Per yarn (core's Weave::yarns()): (ex, ey, rs, width), (cy, noise, 0, 0).
uniform samplerBuffer yarnTable;
uniform ivec2 threadPeriod;  // slots of the warp and of the weft
uniform ivec2 threadSpaced;  // 1 where that side's threads differ in width
#endif
// Area fractions of the surface covered by (weft, warp) yarn on the front (xy) and back (zw)
// face; the rest is gap. They weight the element-averaged reflectance of the weave filter.
uniform vec4 yarnCoverage;
#ifdef WOVEN_FILTER
// core's WeaveFarField::footprintScales(): what a footprint smaller than the repeat sees of each
// colour's lobes (warp, weft, backing), from the share of its box whose cells have the warp on
// top (a twill's diagonals, a satin's dots), so the weave's pattern stays where its threads are
// finer than the pixels. Per face: the table of warp-top cells below and left of each corner of
// the tile ((width + 1) x (height + 1), the tile being weaveTile's size), whether the split
// applies (0: the repeat's shares everywhere), and per colour its share of the repeat, of the
// warp-top cells and of the others.
uniform sampler2D frontWarpTopSums, backWarpTopSums;
uniform int splitsByFootprint[2];
uniform vec3 farShares[2], inWarpCells[2], inWeftCells[2];

float warpTopSum(int face, ivec2 corner) {
    return face == 0 ? texelFetch(frontWarpTopSums, corner, 0).r : texelFetch(backWarpTopSums, corner, 0).r;
}

// The cells' indicator integrated from the tile's corner to x, 0 <= x <= tile: the table
// bilinearly inside a cell (exact for a piecewise-constant function).
float warpTopInTile(int face, vec2 x, ivec2 tile) {
    ivec2 c = min(ivec2(x), tile - 1);
    vec2 f = x - vec2(c);
    return mix(mix(warpTopSum(face, c), warpTopSum(face, c + ivec2(1, 0)), f.x),
               mix(warpTopSum(face, c + ivec2(0, 1)), warpTopSum(face, c + ivec2(1, 1)), f.x), f.y);
}

// From the tile's corner to any x >= 0: whole tiles, then the table inside one.
float warpTopIntegral(int face, vec2 x, ivec2 tile) {
    vec2 size = vec2(tile);
    vec2 q = floor(x / size), r = x - q * size;
    return q.x * q.y * warpTopSum(face, tile) + q.x * warpTopInTile(face, vec2(size.x, r.y), tile) +
           q.y * warpTopInTile(face, vec2(r.x, size.y), tile) + warpTopInTile(face, r, tile);
}

// The factor on each colour's lobes (warp, weft, backing) for the box [e0, e1] in weave elements.
vec3 footprintScales(int face, vec2 e0, vec2 e1) {
    if (splitsByFootprint[face] == 0) return vec3(1.0);
    ivec2 tile = textureSize(weaveTile, 0);
    // The box moved into the first repeat, so the integrals stay small.
    vec2 shift = floor(e0 / vec2(tile)) * vec2(tile);
    vec2 a = e0 - shift, b = e1 - shift;
    float area = (b.x - a.x) * (b.y - a.y);
    if (!(area > 0.0)) return vec3(1.0);
    float warpTop = warpTopIntegral(face, b, tile) - warpTopIntegral(face, vec2(a.x, b.y), tile) -
                    warpTopIntegral(face, vec2(b.x, a.y), tile) + warpTopIntegral(face, a, tile);
    float f = clamp(warpTop / area, 0.0, 1.0);
    vec3 box = f * inWarpCells[face] + (1.0 - f) * inWeftCells[face];
    vec3 shares = farShares[face];
    vec3 scale = vec3(shares.x > 0.0 ? box.x / shares.x : 0.0, shares.y > 0.0 ? box.y / shares.y : 0.0,
                      shares.z > 0.0 ? box.z / shares.z : 0.0);
    float total = box.x + box.y + box.z;
    return total > 0.0 ? scale / total : vec3(1.0);
}
#endif
#if defined(WOVEN_FILTER) && defined(WOVEN_THREADS)
// Per thread slot of the warp and of the weft, mipmapped: (colour x cell width, cell width), so
// a filtered lookup over a pixel's footprint gives the width-weighted mean colour of the
// threads it covers.
uniform sampler1D warpColorTexture, weftColorTexture;

// The mean colour of one side's threads over the pixel's footprint, e + a de/dx + b de/dy for a,
// b in [-1/2, 1/2]: 4 x 4 sub-footprints, each a filtered lookup of a quarter of its size, so a
// stripe narrower than a pixel keeps its share and no thread is counted twice.
vec3 footprintColor(sampler1D colors, int period, float e, float dedx, float dedy) {
    float scale = 1.0 / float(period);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            float x = e + (float(i) - 1.5) * 0.25 * dedx + (float(j) - 1.5) * 0.25 * dedy;
            sum += textureGrad(colors, x * scale, 0.25 * dedx * scale, 0.25 * dedy * scale);
        }
    return sum.rgb / max(sum.a, 1e-6);
}
#endif
