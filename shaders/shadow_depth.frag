// Depth pass of ShadowMaps (shadow_depth.glsl) for the casters that block light.
in vec3 vWorld;

void main() { gl_FragDepth = shadowDepth(vWorld); }
