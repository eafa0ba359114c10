// Linear radiance to the display, as core's displayColor() (core/scene/image_io.cpp): scale by
// 2^exposure, tone-map, clip to [0, 1], sRGB-encode (IEC 61966-2-1).
uniform sampler2D radianceImage;
uniform float exposureScale;
uniform int toneMap;    // core's ToneMap: 0 clamp, 1 Reinhard, 2 ACES (Narkowicz's fit)
uniform ivec2 origin;  // lower-left corner of the viewport in the target

out vec4 displayColor;

vec3 toneMapped(vec3 c) {
    if (toneMap == 1) return c / (1.0 + c);
    if (toneMap == 2) return (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
    return c;
}

float linearToSrgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

void main() {
    vec3 c = texelFetch(radianceImage, ivec2(gl_FragCoord.xy) - origin, 0).rgb * exposureScale;
    c = clamp(toneMapped(max(c, vec3(0.0))), 0.0, 1.0);
    displayColor = vec4(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 1.0);
}
