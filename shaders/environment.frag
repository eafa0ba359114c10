// What rays that miss everything see: core's Light::Le for an environment image (the nearest
// texel of the equirectangular image, turned by the rotation, times the colour; the mapping of
// core/scene/environment_mapping.h).
uniform sampler2D environmentImage;
uniform vec3 environmentColor;
uniform float environmentRotation;  // radians about +y
uniform mat3 cameraRotation;        // camera to world
uniform vec2 tanHalfFov;            // x: horizontal, y: vertical
uniform vec2 viewportSize;

out vec4 outRadiance;

const float PI = 3.14159265358979;

void main() {
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    vec3 d = normalize(cameraRotation * vec3(ndc * tanHalfFov, -1.0));
    float c = cos(-environmentRotation), s = sin(-environmentRotation);
    d = vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
    float phi = atan(d.x, -d.z);
    if (phi < 0.0) phi += 2.0 * PI;
    vec2 uv = vec2(phi / (2.0 * PI), atan(length(d.xz), d.y) / PI);
    ivec2 size = textureSize(environmentImage, 0);
    ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    outRadiance = vec4(environmentColor * texelFetch(environmentImage, texel, 0).rgb, 1.0);
}
