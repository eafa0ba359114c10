// The material of the mesh being drawn. `struct WovenParams` itself is not written here: the
// C++ side generates it from core's wovenParamTable() (app/preview/woven_gl_material.cpp), one
// field per table entry with the same name, and uploads every field by that name. A table entry
// the shaders never read shows up as an inactive uniform, which tests/preview checks.
uniform WovenParams material;

// The weave tile of both faces, texel (U mod P_u, V mod P_v, face): r = 1 where warp is on top,
// g = elements before this one in its float, b = the float's length (WeavePattern::floatAt).
uniform sampler2DArray weaveTile;
// Area fractions of the tile covered by (weft, warp) yarn on the front (xy) and back (zw) face;
// the rest is gap. They weight the element-averaged reflectance of the weave filter.
uniform vec4 yarnCoverage;
