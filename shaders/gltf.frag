// The glTF material's surface shader: core's GltfMaterial (every texture looked up, the normal
// map applied) and gltf_bxdf.glsl lit by lighting.glsl, plus the occlusion texture, which only
// the preview uses. The C++ side (gltf_gl_material.cpp) defines MAP_<NAME> as the index into
// maps[] (texture_maps.glsl) of each texture the material has, MAP_COUNT, ALPHA_MASK or
// ALPHA_BLEND, UNLIT, PREVIEW_SHADOWS and DIFFUSE_TRANSMISSION (KHR_materials_diffuse_transmission:
// the lights behind the surface shine through). BLEND alpha and transmission become screen-door coverage (screen_door.glsl).
layout(location = 0) out vec4 outRadiance;

uniform vec3 cameraPosition;
uniform vec3 emission;  // emissive factor x strength, radiance of the front face
// The material's factors (baseColorFactor, metallicFactor, ...) are declared in the preamble from
// gltfUniformTable() (app/preview/gltf_gl_material.cpp), which also uploads them.

// As core's keepReflectionAbove(): a normal map's normal tilted so far that the view's mirror
// direction falls below the surface is tilted back until it stays `margin` above.
vec3 keepReflectionAbove(vec3 ng, vec3 wo, vec3 n) {
    float cosView = dot(wo, ng);
    float margin = min(0.9 * cosView, 0.01);
    vec3 r = 2.0 * dot(wo, n) * n - wo;
    if (dot(r, ng) >= margin) return n;
    vec3 tangential = r - dot(r, ng) * ng;
    float len = length(tangential);
    if (!(len > 1e-12) || !(cosView > 0.0)) return n;
    vec3 half_ = wo + sqrt(1.0 - margin * margin) * (tangential / len) + margin * ng;
    float halfLength = length(half_);
    return halfLength > 1e-12 ? half_ / halfLength : n;
}

void main() {
    vec3 p = vPosition;
    vec3 wo = normalize(cameraPosition - p);
    vec3 ng = normalize(cross(dFdx(p), dFdy(p)));
    if (dot(ng, wo) < 0.0) ng = -ng;
    bool backSide;
    vec3 ns = seenSide(ng, backSide);

    vec4 base = gltfBaseColor();
#if defined(ALPHA_MASK)
    if (base.a < alphaCutoff) discard;
#elif defined(ALPHA_BLEND)
    if (base.a < ditherThreshold()) discard;
#endif
#ifdef UNLIT
    outRadiance = vec4(max(base.rgb, vec3(0.0)), 1.0);
    return;
#endif

    float anisotropy;
    vec2 direction;
    GltfInputs g = gltfInputs(base.rgb, anisotropy, direction);

    // Thin-walled transmission lets light through where the surface neither reflects nor
    // absorbs it: drawn as partial coverage.
    float through = g.transmission * (1.0 - g.metallic);
    if (through > 0.0 && 1.0 - through < ditherThreshold()) discard;

    vec3 n = ns;
    vec3 t, b;
    bool tangents = tangentSpace(ns, vTangent, t, b);
#ifdef MAP_NORMAL
    if (tangents) n = normalMapped(ns, t, b, lookup(MAP_NORMAL).xyz, normalScale);
#endif
    n = backSide ? -n : n;
#ifdef MAP_NORMAL
    n = keepReflectionAbove(ng, wo, n);  // ng faces the viewer already
#endif
    // The lobe's x axis along the anisotropy direction (any axis when isotropic).
    Frame f = anisotropy > 0.0 && tangents ? frameFromNormalAndAxis(n, direction.x * t + direction.y * b) : frameFromNormal(n);
    vec3 woLocal = toLocal(f, wo);
    float occlusion = 1.0;
#ifdef MAP_OCCLUSION
    occlusion = 1.0 + occlusionStrength * (lookup(MAP_OCCLUSION).r - 1.0);
#endif
    vec3 radiance = ambientSeen * gltfAlbedo(g, woLocal.z) * occlusion;
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, ng, wi);
        if (L == vec3(0.0)) continue;
        vec3 wiLocal = toLocal(f, wi);
        radiance += gltfBsdf(g, woLocal, wiLocal) * L * max(wiLocal.z, 0.0);
    }
#ifdef DIFFUSE_TRANSMISSION
    // The lights on the other side (of -ng), through the surface.
    for (int i = 0; i < lightCount; ++i) {
        vec3 wi;
        vec3 L = incidentLight(i, p, -ng, wi);
        if (L == vec3(0.0)) continue;
        vec3 wiLocal = toLocal(f, wi);
        radiance += gltfDiffuseBtdf(g, woLocal, wiLocal) * L * max(-wiLocal.z, 0.0);
    }
#endif
    if (!backSide) {
        vec3 e = emission;
#ifdef MAP_EMISSIVE
        e *= lookup(MAP_EMISSIVE).rgb;
#endif
        radiance += e;
    }
    outRadiance = vec4(radiance, 1.0);
}
