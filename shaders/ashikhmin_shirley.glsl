// core/model/ashikhmin_shirley.cpp's eval() and frame.cpp in GLSL: the anisotropic specular
// lobe with Schlick Fresnel plus the coupled diffuse term, in a frame with z = the shading
// normal and x = the e_x axis (along the yarn).
const float PI = 3.14159265358979;

struct Frame { vec3 x, y, z; };
struct Lobe { float ex, ey, rs; vec3 rd; };

vec3 toLocal(Frame f, vec3 v) { return vec3(dot(v, f.x), dot(v, f.y), dot(v, f.z)); }
vec3 toWorld(Frame f, vec3 v) { return v.x * f.x + v.y * f.y + v.z * f.z; }

Frame frameFromNormal(vec3 n) {  // Duff et al. 2017, as Frame::fromNormal
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return Frame(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

Frame frameFromNormalAndAxis(vec3 n, vec3 axis) {  // as Frame::fromNormalAndAxis
    vec3 t = axis - dot(axis, n) * n;
    float len2 = dot(t, t);
    if (!(len2 > 1e-20) || isinf(len2)) return frameFromNormal(n);
    vec3 x = t * inversesqrt(len2);
    return Frame(x, cross(n, x), n);
}

float pow5(float x) { return (x * x) * (x * x) * x; }

// log(1 - x), accurate where 1 - x rounds to 1 (GLSL has no log1p), so exponents up to 1e5
// keep their narrow peak.
float log1mx(float x) { return x < 1e-3 ? -x * (1.0 + x * (0.5 + x * (1.0 / 3.0))) : log(1.0 - x); }

// (n.h)^N from sin^2(theta_h).
float cosPowN(float sin2, float N) {
    if (N <= 0.0) return 1.0;  // not 0 * log(0) where h reaches the horizon
    return exp(N * 0.5 * log1mx(min(sin2, 1.0)));
}

vec3 ashikhminShirley(Lobe l, vec3 wo, vec3 wi) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
    vec3 diffuse = (28.0 / (23.0 * PI)) * l.rd * (1.0 - l.rs) * (1.0 - pow5(1.0 - 0.5 * wo.z)) *
                   (1.0 - pow5(1.0 - 0.5 * wi.z));
    vec3 H = wo + wi;
    float len = length(H);
    if (!(len > 1e-12)) return diffuse;
    vec3 h = H / len;
    float hk = 0.5 * len;  // h.k = |k1 + k2| / 2: reciprocal, and exact as h.k -> 0
    float fresnel = l.rs + (1.0 - l.rs) * pow5(1.0 - hk);
    float sx = h.x * h.x, sy = h.y * h.y, s = sx + sy;
    float N = s > 0.0 ? (l.ex * sx + l.ey * sy) / s : l.ex;
    float spec = sqrt((l.ex + 1.0) * (l.ey + 1.0)) / (8.0 * PI) * cosPowN(s, N) / (hk * max(wo.z, wi.z)) * fresnel;
    return diffuse + vec3(spec);
}

// Hemispherical reflectance seen from direction wo (local): the diffuse term integrates in
// closed form to R_d (1 - R_s)(1 - (1 - n.k1 / 2)^5); the specular lobe's is close to the
// Schlick Fresnel at n.k1, which A-S's normalisation was designed for.
vec3 ashikhminShirleyAlbedo(Lobe l, float cosO) {
    if (cosO <= 0.0) return vec3(0.0);
    return l.rd * (1.0 - l.rs) * (1.0 - pow5(1.0 - 0.5 * cosO)) + vec3(l.rs + (1.0 - l.rs) * pow5(1.0 - cosO));
}
