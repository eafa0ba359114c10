// The scene's lights as the preview sees them (app/preview/preview_lights.cpp builds the list):
// point, spot and directional lights as they are, emissive triangles as a few point-like
// samples each, and the environment as a constant ambient radiance integrated against the lobe.
// No shadows.
#define MAX_LIGHTS 32
const int LIGHT_POINT = 0, LIGHT_SPOT = 1, LIGHT_DIRECTIONAL = 2, LIGHT_AREA = 3, LIGHT_AREA_TWO_SIDED = 4;

uniform int lightCount;
uniform vec4 lightPosition[MAX_LIGHTS];   // xyz: position, or the direction travelled (directional); w: type
uniform vec4 lightAxis[MAX_LIGHTS];       // spot: direction travelled, w = cos(outer); area: unit normal
uniform vec4 lightIntensity[MAX_LIGHTS];  // rgb: W/sr, W/m^2, or radiance x area (area); w: spot cos(inner)
uniform vec3 ambientRadiance;

// Radiance arriving at p from light i along -wi (before the cosine); wi points to the light.
vec3 incidentLight(int i, vec3 p, out vec3 wi) {
    int type = int(lightPosition[i].w);
    vec3 intensity = lightIntensity[i].rgb;
    if (type == LIGHT_DIRECTIONAL) {
        wi = -normalize(lightPosition[i].xyz);
        return intensity;
    }
    vec3 d = lightPosition[i].xyz - p;
    float dist2 = max(dot(d, d), 1e-12);
    wi = d * inversesqrt(dist2);
    if (type == LIGHT_SPOT) {
        // glTF KHR_lights_punctual's smooth falloff between the outer and inner cone.
        float cosAngle = dot(-wi, lightAxis[i].xyz);
        float t = clamp((cosAngle - lightAxis[i].w) / max(lightIntensity[i].w - lightAxis[i].w, 1e-4), 0.0, 1.0);
        intensity *= t * t;
    } else if (type >= LIGHT_AREA) {
        float cosLight = dot(-wi, lightAxis[i].xyz);
        intensity *= type == LIGHT_AREA_TWO_SIDED ? abs(cosLight) : max(cosLight, 0.0);
    }
    return intensity / dist2;
}

// Light reflected towards wo by a lobe in frame f at p. `ng`: the geometric normal on the
// viewer's side; light from below the surface does not reach a reflecting cloth.
vec3 reflectedLight(Frame f, Lobe lobe, vec3 p, vec3 ng, vec3 wo) {
    vec3 woLocal = toLocal(f, wo);
    vec3 sum = ambientRadiance * ashikhminShirleyAlbedo(lobe, woLocal.z);
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, wi);
        if (dot(wi, ng) <= 0.0) continue;
        vec3 wiLocal = toLocal(f, wi);
        sum += ashikhminShirley(lobe, woLocal, wiLocal) * L * max(wiLocal.z, 0.0);
    }
    return sum;
}
