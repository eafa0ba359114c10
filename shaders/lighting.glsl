// The scene's lights as the preview sees them (app/preview/preview_lights.cpp builds the list):
// point, spot and directional lights as they are, emissive triangles as a few point-like
// samples each, the environment's brightest regions as directional lights and the rest of it as
// a constant ambient radiance integrated against the lobe, weighed by the share of the sky the
// vertices see, plus one bounce of light off the scene (mesh_varyings.glsl). With
// PREVIEW_SHADOWS, the strongest lights are occluded through ShadowMaps
// (app/preview/shadow_maps.cpp).
// PREVIEW_TRANSMITTED_SHADOWS adds the occluders that let coloured light through.
#define MAX_LIGHTS 32
const int LIGHT_POINT = 0, LIGHT_SPOT = 1, LIGHT_DIRECTIONAL = 2, LIGHT_AREA = 3, LIGHT_AREA_TWO_SIDED = 4;

uniform int lightCount;
uniform vec4 lightPosition[MAX_LIGHTS];   // xyz: position, or the direction travelled (directional); w: type
uniform vec4 lightAxis[MAX_LIGHTS];       // spot: direction travelled, w = cos(outer); area: unit normal
uniform vec4 lightIntensity[MAX_LIGHTS];  // rgb: W/sr, W/m^2, or radiance x area (area); w: spot cos(inner)
uniform vec3 ambientRadiance;
// The ambient as it reaches the shaded point, on the side seen and on the other: ambientRadiance
// times that side's share of the sky, as the path tracer's environment is occluded (a fold, the
// floor below), plus the light bounced to that side off the scene (a room's ceiling, the floor
// below a hem). Set by ambientAt() before a surface shader lights anything.
vec3 ambientSeen, ambientBehind;
void ambientAt(bool backSide) {
    vec2 share = backSide ? vSkyVisibility.yx : vSkyVisibility;
    ambientSeen = ambientRadiance * share.x + (backSide ? vBouncedBack : vBouncedFront);
    ambientBehind = ambientRadiance * share.y + (backSide ? vBouncedFront : vBouncedBack);
}

// The side seen, as core's: the triangle's winding side (SurfaceHit::ng). In a fold seen edge-on
// the vertex normals may face away from it; they are turned to it as core turns them (nsFlipped),
// or the side of the vertex normal would show a woven cloth's back there. Returns the shading
// normal on the winding side and sets the ambient of the side of the vertex normal seen (the sky
// and the bounce are kept per vertex normal). `ng`: the geometric normal, facing the viewer.
vec3 seenSide(vec3 ng, out bool backSide) {
    backSide = !gl_FrontFacing;
    vec3 windingNormal = backSide ? -ng : ng;
    vec3 ns = dot(vNormal, vNormal) > 0.0 ? normalize(vNormal) : windingNormal;
    bool nsFlipped = dot(ns, windingNormal) < 0.0;
    ambientAt(backSide != nsFlipped);
    return nsFlipped ? -ns : ns;
}

#ifdef PREVIEW_SHADOWS
#define MAX_SHADOW_MAPS 8
uniform samplerCubeArrayShadow shadowCubes;  // distance to the light / shadowFar
uniform sampler2DArrayShadow shadowFlats;    // perspective or orthographic depth
uniform int shadowCube[MAX_LIGHTS];          // the light's cube map, -1: none
uniform int shadowFlat[MAX_LIGHTS];          // the light's flat map, -1: none
uniform float shadowFar[MAX_LIGHTS];
uniform mat4 flatMatrix[MAX_SHADOW_MAPS];
uniform vec2 flatTexel[MAX_SHADOW_MAPS];     // texel size: x world units, + y per unit of distance
uniform float cubeSize;

#ifdef PREVIEW_TRANSMITTED_SHADOWS
// The nearest occluder that lets light through (a woven cloth whose yarns transmit, a glTF
// material with diffuse transmission), kept apart from the opaque ones: its depth as above and,
// per texel, the share of the light it passes (woven_shadow.frag, gltf_shadow.frag; white where
// there is none).
uniform samplerCubeArrayShadow transmittedCubes;
uniform samplerCubeArray transmittedCubeColors;
uniform sampler2DArrayShadow transmittedFlats;
uniform sampler2DArray transmittedFlatColors;
#endif

// Which of the first lights the vertices see, traced on the BVH (bounced_light.h's lightsSeen):
// a fold's shadow on the cloth beside it, finer than a map's texel and its offset.
#define VERTEX_SHADOW_LIGHTS 8
float vertexSeesLight(int i) { return i < VERTEX_SHADOW_LIGHTS ? vLightsSeen[i / 4][i % 4] : 1.0; }

// Fraction of light i that reaches p, per colour. The lookup point moves two shadow-map texels
// along the geometric normal `ng` (on the light's side), so a surface does not shadow itself.
// Behind a transmitting occluder, the light is what it passes; the filtered comparison blends
// that in across the occluder's edge as it does the opaque shadow's. The colour is looked up
// only there, and the transmitted depth only where the opaque map lets light through.
vec3 lightVisibility(int i, vec3 p, vec3 ng) {
    int c = shadowCube[i];
    if (c >= 0) {
        float texel = 2.0 * distance(p, lightPosition[i].xyz) / cubeSize;
        vec3 d = p + ng * (2.0 * texel) - lightPosition[i].xyz;
        vec4 at = vec4(d, float(c));
        float depth = length(d) / shadowFar[i];
        vec3 visible = vec3(texture(shadowCubes, at, depth));
#ifdef PREVIEW_TRANSMITTED_SHADOWS
        float behind = visible.r > 0.0 ? 1.0 - texture(transmittedCubes, at, depth) : 0.0;
        if (behind > 0.0) visible *= mix(vec3(1.0), texture(transmittedCubeColors, at).rgb, behind);
#endif
        return visible;
    }
    int f = shadowFlat[i];
    if (f < 0) return vec3(1.0);
    // (For a directional light lightPosition is a direction and flatTexel[f].y is 0.)
    float texel = flatTexel[f].x + flatTexel[f].y * distance(p, lightPosition[i].xyz);
    vec4 q = flatMatrix[f] * vec4(p + ng * (2.0 * texel), 1.0);
    vec3 t = q.xyz / q.w * 0.5 + 0.5;
    if (any(lessThan(t, vec3(0.0))) || any(greaterThan(t, vec3(1.0)))) return vec3(1.0);
    vec3 visible = vec3(texture(shadowFlats, vec4(t.xy, float(f), t.z)));
#ifdef PREVIEW_TRANSMITTED_SHADOWS
    float behind = visible.r > 0.0 ? 1.0 - texture(transmittedFlats, vec4(t.xy, float(f), t.z)) : 0.0;
    if (behind > 0.0) visible *= mix(vec3(1.0), texture(transmittedFlatColors, vec3(t.xy, float(f))).rgb, behind);
#endif
    return visible;
}
#endif

// Radiance arriving at p from light i along -wi (before the cosine); wi points to the light.
// `ng`: the geometric normal on the viewer's side; light from below the surface does not reach a
// reflecting cloth.
vec3 incidentLight(int i, vec3 p, vec3 ng, out vec3 wi) {
    int type = int(lightPosition[i].w);
    vec3 intensity = lightIntensity[i].rgb;
    if (type == LIGHT_DIRECTIONAL) {
        wi = -normalize(lightPosition[i].xyz);
    } else {
        vec3 d = lightPosition[i].xyz - p;
        float dist2 = max(dot(d, d), 1e-12);
        wi = d * inversesqrt(dist2);
        intensity /= dist2;
    }
    if (dot(wi, ng) <= 0.0) return vec3(0.0);
    if (type == LIGHT_SPOT) {
        // glTF KHR_lights_punctual's smooth falloff between the outer and inner cone.
        float cosAngle = dot(-wi, lightAxis[i].xyz);
        float t = clamp((cosAngle - lightAxis[i].w) / max(lightIntensity[i].w - lightAxis[i].w, 1e-4), 0.0, 1.0);
        intensity *= t * t;
    } else if (type >= LIGHT_AREA) {
        float cosLight = dot(-wi, lightAxis[i].xyz);
        intensity *= type == LIGHT_AREA_TWO_SIDED ? abs(cosLight) : max(cosLight, 0.0);
    }
#ifdef PREVIEW_SHADOWS
    intensity *= min(lightVisibility(i, p, ng), vec3(vertexSeesLight(i)));
#endif
    return intensity;
}
