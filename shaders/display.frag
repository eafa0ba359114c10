// Linear radiance to the display, as core's writePng with ToneMap::Clamp does: scale by
// 2^exposure, clip to [0, 1], sRGB-encode (IEC 61966-2-1).
uniform sampler2D radianceImage;
uniform float exposureScale;
uniform ivec2 origin;  // lower-left corner of the viewport in the target

out vec4 displayColor;

float linearToSrgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

void main() {
    vec3 c = clamp(texelFetch(radianceImage, ivec2(gl_FragCoord.xy) - origin, 0).rgb * exposureScale, 0.0, 1.0);
    displayColor = vec4(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 1.0);
}
