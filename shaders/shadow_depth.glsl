// The depth ShadowMaps stores for a world point: on cube faces the distance to the light over
// `far`, so one comparison serves all six faces; on flat maps the rasterised depth. Shared by the
// depth pass (shadow_depth.frag) and the transmittance pass of cloth that lets light through
// (woven_shadow.frag, gltf_shadow.frag).
uniform vec4 shadowLight;  // xyz: the light's position (w = 1), or the direction it travels (w = 0)
uniform float far;         // a cube's far distance; 0: a flat map

float shadowDepth(vec3 p) { return far > 0.0 ? distance(p, shadowLight.xyz) / far : gl_FragCoord.z; }

// The unit direction from p towards the light.
vec3 towardsShadowLight(vec3 p) {
    return shadowLight.w > 0.0 ? normalize(shadowLight.xyz - p) : -normalize(shadowLight.xyz);
}
