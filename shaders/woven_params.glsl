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
// finer than the pixels. The front face's table of warp-top cells below and left of each corner of
// the tile ((width + 1) x (height + 1), the tile being weaveTile's size; the back face's warp-top
// cells are the front's others); per face whether the split applies (0: the repeat's shares
// everywhere), and per colour its share of the repeat, of the warp-top cells and of the others.
uniform sampler2D warpTopSums;
uniform int splitsByFootprint[2];
uniform vec3 farShares[2], inWarpCells[2], inWeftCells[2];

// The integral over the box [e0, e1] of a function constant on each unit cell and periodic over
// `size` cells, from its table of sums below and left of each corner, at `origin` in `sums`
// (core's periodicBoxIntegral): the box moved into the first period, so the sums stay small,
// then whole periods and the table bilinearly inside one (exact for a piecewise-constant function).
vec4 inPeriod(sampler2D sums, ivec2 origin, vec2 x, ivec2 size) {
    ivec2 c = origin + min(ivec2(x), size - 1);
    vec2 f = x - vec2(c - origin);
    return mix(mix(texelFetch(sums, c, 0), texelFetch(sums, c + ivec2(1, 0), 0), f.x),
               mix(texelFetch(sums, c + ivec2(0, 1), 0), texelFetch(sums, c + ivec2(1, 1), 0), f.x), f.y);
}
vec4 integralTo(sampler2D sums, ivec2 origin, vec2 x, ivec2 size) {
    vec2 period = vec2(size);
    vec2 q = floor(x / period), r = x - q * period;
    return q.x * q.y * texelFetch(sums, origin + size, 0) + q.x * inPeriod(sums, origin, vec2(period.x, r.y), size) +
           q.y * inPeriod(sums, origin, vec2(r.x, period.y), size) + inPeriod(sums, origin, r, size);
}
vec4 periodicBoxIntegral(sampler2D sums, ivec2 origin, ivec2 size, vec2 e0, vec2 e1) {
    vec2 shift = floor(e0 / vec2(size)) * vec2(size);
    vec2 a = e0 - shift, b = e1 - shift;
    return integralTo(sums, origin, b, size) - integralTo(sums, origin, vec2(a.x, b.y), size) -
           integralTo(sums, origin, vec2(b.x, a.y), size) + integralTo(sums, origin, a, size);
}

// The factor on each colour's lobes (warp, weft, backing) for the box [e0, e1] in weave elements.
vec3 footprintScales(int face, vec2 e0, vec2 e1) {
    if (splitsByFootprint[face] == 0) return vec3(1.0);
    ivec2 tile = textureSize(weaveTile, 0);
    float area = (e1.x - e0.x) * (e1.y - e0.y);
    if (!(area > 0.0)) return vec3(1.0);
    float warpTop = periodicBoxIntegral(warpTopSums, ivec2(0), tile, e0, e1).r;
    float f = clamp((face == 0 ? warpTop : area - warpTop) / area, 0.0, 1.0);
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

// core's WeaveFarField::footprintColors(): each side's colours over the box [e0, e1] weighted by
// each cell's share of that side's yarn, from the front face's tables of (warp-top cells x the
// side's colour, warp-top cells) over the joint period of the tile and the side's colours (the
// back face's warp-top cells are the front's others): the warp's at (0, 0) of colorTopSums, the
// weft's below it. `warp` and `weft`: the plain means in, the weighted ones out.
uniform sampler2D colorTopSums;
uniform ivec4 colorTableSizes;  // the warp's table (xy) and the weft's (zw) in cells; 0 where unused

void footprintColors(int face, vec2 e0, vec2 e1, inout vec3 warp, inout vec3 weft) {
    float area = (e1.x - e0.x) * (e1.y - e0.y);
    if (splitsByFootprint[face] == 0 || !(area > 0.0)) return;
    for (int side = 0; side < 2; ++side) {
        ivec2 size = side == 0 ? colorTableSizes.xy : colorTableSizes.zw;
        if (size.x == 0) continue;
        vec4 s = periodicBoxIntegral(colorTopSums, ivec2(0, side == 0 ? 0 : colorTableSizes.y + 1), size, e0, e1);
        vec3 all = (side == 0 ? warp : weft) * area;
        float warpTop = clamp(s.a, 0.0, area);
        if (face == 1) {
            s.rgb = all - s.rgb;
            warpTop = area - warpTop;
        }
        vec3 topColor = side == 0 ? s.rgb : all - s.rgb, otherColor = all - topColor;
        float top = side == 0 ? warpTop : area - warpTop;
        float inTop = side == 0 ? inWarpCells[face].x : inWeftCells[face].y;
        float inOther = side == 0 ? inWeftCells[face].x : inWarpCells[face].y;
        float weight = inTop * top + inOther * (area - top);
        if (weight > 1e-6 * area) {
            vec3 c = (inTop * topColor + inOther * otherColor) / weight;
            if (side == 0) warp = c;
            else weft = c;
        }
    }
}
#endif
