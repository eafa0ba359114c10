// core/model/yarn_geometry.cpp in GLSL: which yarn is seen at a UV point (the weave tile, then
// the yarn widths), where along it, and its bumped normal from c_y and the crimp.
const int WEFT = 0, WARP = 1, GAP = 2;

struct YarnPoint {
    int type;
    int yarnIndex;  // row V for weft, column U for warp
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

YarnPoint yarnAt(vec2 uv, int face) {
    vec2 e = uv * material.repeat;
    vec2 cell = floor(e);
    vec2 st = e - cell;
    ivec2 size = textureSize(weaveTile, 0).xy;
    vec4 texel = texelFetch(weaveTile, ivec3(positiveMod(cell.x, size.x), positiveMod(cell.y, size.y), face), 0);
    bool warpOnTop = texel.r > 0.5;

    float xWeft = (st.y - 0.5) / (0.5 * material.yarn_width);
    float xWarp = (st.x - 0.5) / (0.5 * material.warp_width);
    bool onTop = warpOnTop ? abs(xWarp) <= 1.0 : abs(xWeft) <= 1.0;
    bool onCrossing = warpOnTop ? abs(xWeft) <= 1.0 : abs(xWarp) <= 1.0;
    if (!onTop && !onCrossing) return YarnPoint(GAP, 0, 0.0, vec3(0.0, 0.0, 1.0));
    bool onWeft = warpOnTop != onTop;
    // The crossing yarn seen in the gap beside the top yarn dips under it: no crimp there.
    if (onWeft) {
        float slope = onTop ? crimpSlope(texel.gb, st.x) : 0.0;
        return YarnPoint(WEFT, int(cell.y), e.x, yarnNormal(0, material.cy, xWeft, slope));
    }
    float slope = onTop ? crimpSlope(texel.gb, st.y) : 0.0;
    return YarnPoint(WARP, int(cell.x), e.y, yarnNormal(1, material.cy, xWarp, slope));
}
