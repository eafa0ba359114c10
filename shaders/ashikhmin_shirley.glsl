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

// A half vector drawn from the lobe's density, sqrt((e_x + 1)(e_y + 1)) / (2 pi) (n.h)^N, as
// core's AshikhminShirley::sampleHalfVector() (A-S's tan mapping of phi, mirrored per quadrant).
vec3 ashikhminShirleyHalfVector(Lobe l, vec2 u) {
    float a = u.x * 4.0;
    int quadrant = min(int(a), 3);
    float uq = a - float(quadrant);
    if (quadrant == 1 || quadrant == 3) uq = 1.0 - uq;
    float angle = 0.5 * PI * uq;
    vec2 dir = normalize(vec2(sqrt(l.ey + 1.0) * cos(angle), sqrt(l.ex + 1.0) * sin(angle)));
    if (quadrant == 1 || quadrant == 2) dir.x = -dir.x;
    if (quadrant >= 2) dir.y = -dir.y;
    float N = l.ex * dir.x * dir.x + l.ey * dir.y * dir.y;
    // 1 - cos(theta) = -expm1(log(1 - u.y) / (N + 1)), accurate where N is large.
    float x = log1mx(u.y) / (N + 1.0);
    float oneMinusCos = x > -1e-3 ? -x * (1.0 + 0.5 * x) : 1.0 - exp(x);
    float cosTheta = 1.0 - oneMinusCos;
    return vec3(sqrt(max(0.0, oneMinusCos * (1.0 + cosTheta))) * dir, cosTheta);
}

// The lobe's reflectance seen from wo (local) of a constant radiance from every direction above
// both the shading and the geometric surface (`ng`, local, on wo's side): core's path tracer
// reflects no light from below the geometric surface (integrator.h's connects()), which a yarn
// tilted by its curvature would otherwise take. The diffuse term integrates in closed form to
// R_d (1 - R_s)(1 - (1 - n.k1 / 2)^5) over the shading hemisphere, of which a cosine-weighted
// (1 + n.ng) / 2 lies above the geometric one. The specular lobe has no closed form (its
// integral falls below the Schlick Fresnel at n.k1 at grazing angles, where the lobe reaches
// below the horizon): it is averaged over half vectors drawn from its density on a fixed
// Fibonacci lattice, each weighing F(k1.h) wi.z / max(wo.z, wi.z) (the lobe x cosine / density).
const int ALBEDO_SAMPLES = 8, ALBEDO_STEP = 5;  // consecutive Fibonacci numbers
// The lobe's half vectors for ashikhminShirleyAlbedo(), drawn once where one lobe is seen from
// several directions (the far field's cross-section).
struct AlbedoHalfVectors { vec3 h[ALBEDO_SAMPLES]; };
AlbedoHalfVectors albedoHalfVectors(Lobe l) {
    AlbedoHalfVectors hv;
    for (int i = 0; i < ALBEDO_SAMPLES; ++i) {
        vec2 u = vec2((float(i) + 0.5) / float(ALBEDO_SAMPLES), fract((float(i * ALBEDO_STEP) + 0.5) / float(ALBEDO_SAMPLES)));
        hv.h[i] = ashikhminShirleyHalfVector(l, u);
    }
    return hv;
}
vec3 ashikhminShirleyAlbedo(Lobe l, AlbedoHalfVectors hv, vec3 wo, vec3 ng) {
    if (wo.z <= 0.0) return vec3(0.0);
    float spec = 0.0;
    for (int i = 0; i < ALBEDO_SAMPLES; ++i) {
        float oh = dot(wo, hv.h[i]);
        if (oh <= 0.0) continue;
        vec3 wi = 2.0 * oh * hv.h[i] - wo;
        if (wi.z <= 0.0 || dot(wi, ng) <= 0.0) continue;
        spec += (l.rs + (1.0 - l.rs) * pow5(1.0 - oh)) * wi.z / max(wo.z, wi.z);
    }
    return l.rd * (1.0 - l.rs) * (1.0 - pow5(1.0 - 0.5 * wo.z)) * (0.5 + 0.5 * clamp(ng.z, -1.0, 1.0)) +
           vec3(spec / float(ALBEDO_SAMPLES));
}
vec3 ashikhminShirleyAlbedo(Lobe l, vec3 wo, vec3 ng) { return ashikhminShirleyAlbedo(l, albedoHalfVectors(l), wo, ng); }
