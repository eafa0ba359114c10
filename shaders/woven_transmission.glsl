// core's yarn transmission (core/model/yarn_transmission.cpp, docs/MODEL_TRANSMISSION.md) for
// woven.frag's shading and woven_shadow.frag's coloured shadows. Included with
// WOVEN_TRANSMISSION only.
#ifdef WOVEN_TRANSMISSION

// core's yarnTransmittance: T of a yarn of diffuse colour rd passing the fraction t.
vec3 yarnTransmittance(vec3 rd, float t) {
    float peak = max(rd.r, max(rd.g, rd.b));
    if (!(peak > 0.0)) return vec3(0.0);
    vec3 hue = rd / peak;
    return t * (1.0 - rd) * hue * hue;
}

// E(mu): the share of the light past the specular coat that enters the yarn's body at cosine mu.
float enteringFraction(float mu) { return 1.0 - pow5(1.0 - 0.5 * mu); }

// core's YarnTransmission::eval.
vec3 yarnTransmission(Lobe l, vec3 T, float g, vec3 wo, vec3 wi) {
    if (wo.z * wi.z >= 0.0) return vec3(0.0);
    float mo = abs(wo.z), mi = abs(wi.z);
    float lobe = (1.0 - g) * (28.0 / (23.0 * PI));
    vec3 H = vec3(wo.xy + wi.xy, mo + mi);
    float len = length(H);
    if (g > 0.0 && len > 1e-12) {
        vec3 h = H / len;
        float sx = h.x * h.x, sy = h.y * h.y, s = sx + sy;
        float N = s > 0.0 ? (l.ex * sx + l.ey * sy) / s : l.ex;
        lobe += g * sqrt((l.ex + 1.0) * (l.ey + 1.0)) / (8.0 * PI) * cosPowN(s, N) / (0.5 * len * max(mo, mi));
    }
    return T * ((1.0 - l.rs) * enteringFraction(mo) * enteringFraction(mi) * lobe);
}

// The share of the light arriving at cosine mu that yarnTransmission() passes to the other side,
// all directions together: the diffuse part's albedo is exactly (1 - g) T (1 - R_s) E(mu), the
// glossy part's at most g T (1 - R_s) E(mu) (docs/MODEL_TRANSMISSION.md section 4); both are
// taken at that bound, which overstates the glossy part by the E and cosine factors of its
// outgoing directions (under a fifth at the default gloss, light near the normal).
vec3 yarnTransmittedAlbedo(Lobe l, vec3 T, float mu) { return T * ((1.0 - l.rs) * enteringFraction(mu)); }

// The T that a crossing of the material's own warp and weft yarns passes (the smaller of the two,
// as core's WovenMaterial::shade), and each yarn's (t, g) in `weftT` and `warpT`.
vec3 ownYarnsTransmittance(Lobe weft, Lobe warp, out vec2 weftT, out vec2 warpT) {
#ifdef WOVEN_THREADS
    weftT = yarnTexel(1, 1).zw;
    warpT = yarnTexel(0, 1).zw;
#else
    weftT = vec2(material.transmission, material.transmission_gloss);
    warpT = weftT;
#endif
    return min(yarnTransmittance(weft.rd, weftT.x), yarnTransmittance(warp.rd, warpT.x));
}
#endif
