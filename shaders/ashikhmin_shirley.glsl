// core/model/ashikhmin_shirley.cpp's eval() in GLSL: the anisotropic specular lobe with
// Schlick Fresnel plus the coupled diffuse term, in a frame with z = the shading normal and
// x = the e_x axis (along the yarn).
struct Lobe { float ex, ey, rs; vec3 rd; };

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
