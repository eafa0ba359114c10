// Transmittance pass of ShadowMaps for a glTF material with KHR_materials_diffuse_transmission:
// per colour, the share of a light's beam that its diffuse transmission passes to the other side,
// which lighting.glsl multiplies into that light where a point lies behind it. The BTDF
// (gltf_bxdf.glsl) is Lambertian but for its Fresnel and layer factors, so its albedo is pi times
// its value, those factors taken towards the mirrored direction (Fresnel at normal incidence).
// MASK cut-outs pass everything, BLEND alpha the rest of the light; thin transmission
// (KHR_materials_transmission) and the normal map are left out.
layout(location = 0) out vec4 outTransmittance;

void main() {
    vec3 p = vPosition;
    gl_FragDepth = shadowDepth(p);
    vec4 base = gltfBaseColor();
#ifdef ALPHA_MASK
    if (base.a < alphaCutoff) discard;
#endif
    float anisotropy;
    vec2 direction;
    GltfInputs g = gltfInputs(base.rgb, anisotropy, direction);
    vec3 ng = cross(dFdx(p), dFdy(p));
    float mu = dot(ng, ng) > 0.0 ? abs(dot(normalize(ng), towardsShadowLight(p))) : 1.0;
    float across = sqrt(max(0.0, 1.0 - mu * mu));
    vec3 through = PI * gltfDiffuseBtdf(g, vec3(across, 0.0, mu), vec3(across, 0.0, -mu));
#ifdef ALPHA_BLEND
    through = mix(vec3(1.0), through, clamp(base.a, 0.0, 1.0));
#endif
    outTransmittance = vec4(through, 1.0);
}
