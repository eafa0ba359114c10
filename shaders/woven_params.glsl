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
