// core/model/yarn_geometry.cpp in GLSL: which thread is seen at a UV point (the threads of both
// sides, the weave tile, then the yarn widths), where along it, and its bumped normal from its
// yarn's c_y and the crimp.
const int WEFT = 0, WARP = 1, GAP = 2;

struct YarnPoint {
    int type;
    int yarnIndex;  // row V for weft, column U for warp
    int slot;       // the thread's slot: its colour in threadTable
    int yarn;       // its yarn: 0 the warp's own, 1 the weft's own, else a row of yarnTable
    float along;    // element units along the yarn
    vec3 normal;    // tangent frame: x = +u, y = +v, z = surface normal
};

vec2 crossSectionNormal(float cy, float x) {
    float up = sqrt(max(0.0, 1.0 - x * x));
    vec2 n = vec2(cy * x, up);
    float len = length(n);
    return len > 1e-12 ? n / len : vec2(0.0, 1.0);
}

// h(q) = crimp (1 - 1/L) sin(pi q) along a float of L elements: its slope at the point.
float crimpSlope(vec2 floatPositionLength, float alongInElement) {
#ifdef WOVEN_CRIMP
    float L = floatPositionLength.y;
    if (L <= 1.0) return 0.0;
    float q = (floatPositionLength.x + alongInElement) / L;
    return material.crimp * (1.0 - 1.0 / L) * PI / L * cos(PI * q);
#else
    return 0.0;
#endif
}

vec3 yarnNormal(int alongAxis, float cy, float x, float slope) {
    vec2 section = crossSectionNormal(cy, x);
    float inv = inversesqrt(1.0 + slope * slope);
    vec3 n;
    n[alongAxis] = -slope * inv * section.y;
    n[1 - alongAxis] = section.x;
    n.z = inv * section.y;
    return n;
}

// a mod m in [0, m) for whole floats a of any sign (GLSL's % is undefined for negatives).
int positiveMod(float a, int m) {
    float r = a - float(m) * floor(a / float(m));
    int i = int(r);
    return i >= m ? i - m : (i < 0 ? i + m : i);
}

// core's ThreadLayout::locate: the thread at position e (in mean thread widths) of side 0
// (warp ends along u) or 1 (weft picks along v). `thread` is a whole float.
struct ThreadCell {
    float thread;
    float across;  // [0, 1) across the thread's cell
    int slot;      // thread mod the side's period: its row of threadTable
};

#ifdef WOVEN_THREADS
vec4 threadTexel(int side, int slot, int k) {
    return texelFetch(threadTable, 2 * (slot + (side == 0 ? 0 : threadPeriod.x)) + k);
}
vec4 yarnTexel(int yarn, int k) { return texelFetch(yarnTable, 2 * yarn + k); }
#endif

ThreadCell locateThread(float e, int side) {
#ifdef WOVEN_SPACING
    if (threadSpaced[side] != 0) {
        int n = threadPeriod[side];
        float q = floor(e / float(n));
        float r = clamp(e - q * float(n), 0.0, float(n));
        int b = min(int(r), n - 1);
        int lo = int(threadTexel(side, b, 1).z);
        int hi = b + 1 < n ? int(threadTexel(side, b + 1, 1).z) : n - 1;
        // The last slot in [lo, hi] that starts at or before r.
        while (lo < hi) {
            int mid = (lo + hi + 1) / 2;
            if (threadTexel(side, mid, 1).x <= r) lo = mid;
            else hi = mid - 1;
        }
        vec4 cell = threadTexel(side, lo, 1);
        return ThreadCell(q * float(n) + float(lo), clamp((r - cell.x) / cell.y, 0.0, 1.0), lo);
    }
#endif
    float f = floor(e);
#ifdef WOVEN_THREADS
    return ThreadCell(f, e - f, positiveMod(f, threadPeriod[side]));
#else
    return ThreadCell(f, e - f, 0);
#endif
}

YarnPoint yarnAt(vec2 uv, int face) {
    vec2 e = uv * material.repeat;
    ThreadCell end = locateThread(e.x, 0), pick = locateThread(e.y, 1);
    ivec2 size = textureSize(weaveTile, 0);
    ivec2 cell = ivec2(positiveMod(end.thread, size.x), positiveMod(pick.thread, size.y));
    bool warpOnTop = (texelFetch(weaveTile, cell, 0).r != 0u) != (face == 1);

    // Each crossing thread's yarn: the material's own, or its row of the yarn table.
#ifdef WOVEN_THREADS
    int warpYarn = int(threadTexel(0, end.slot, 0).w), weftYarn = int(threadTexel(1, pick.slot, 0).w);
    float warpWidth = yarnTexel(warpYarn, 0).w, weftWidth = yarnTexel(weftYarn, 0).w;
    float warpCy = yarnTexel(warpYarn, 1).x, weftCy = yarnTexel(weftYarn, 1).x;
#else
    int warpYarn = 0, weftYarn = 1;
    float warpWidth = material.warp_width, weftWidth = material.yarn_width;
    float warpCy = material.cy, weftCy = material.cy;
#endif
    float xWeft = (pick.across - 0.5) / (0.5 * weftWidth);
    float xWarp = (end.across - 0.5) / (0.5 * warpWidth);
    bool onTop = warpOnTop ? abs(xWarp) <= 1.0 : abs(xWeft) <= 1.0;
    bool onCrossing = warpOnTop ? abs(xWeft) <= 1.0 : abs(xWarp) <= 1.0;
    if (!onTop && !onCrossing) return YarnPoint(GAP, 0, 0, 0, 0.0, vec3(0.0, 0.0, 1.0));
    bool onWeft = warpOnTop != onTop;
    // The top yarn's float along its row (weft) or column (warp), for the crimp.
#ifdef WOVEN_CRIMP
    uvec4 runs = texelFetch(weaveFloats, cell, 0);
    vec2 floatPositionLength = onWeft ? vec2(runs.x, runs.y + 1u) : vec2(runs.z, runs.w + 1u);
#else
    vec2 floatPositionLength = vec2(0.0, 1.0);
#endif
    // The crossing yarn seen in the gap beside the top yarn dips under it: no crimp there.
    if (onWeft) {
        float slope = onTop ? crimpSlope(floatPositionLength, end.across) : 0.0;
        return YarnPoint(WEFT, int(pick.thread), pick.slot, weftYarn, e.x, yarnNormal(0, weftCy, xWeft, slope));
    }
    float slope = onTop ? crimpSlope(floatPositionLength, pick.across) : 0.0;
    return YarnPoint(WARP, int(end.thread), end.slot, warpYarn, e.y, yarnNormal(1, warpCy, xWarp, slope));
}
