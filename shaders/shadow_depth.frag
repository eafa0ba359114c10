// Depth pass of ShadowMaps: cube faces store the distance to the light over `far`, so one
// comparison serves all six faces; orthographic (directional) maps keep the rasterised depth.
in vec3 vWorld;

uniform vec3 lightPosition;
uniform float far;  // 0: keep gl_FragCoord.z

void main() {
    gl_FragDepth = far > 0.0 ? distance(vWorld, lightPosition) / far : gl_FragCoord.z;
}
