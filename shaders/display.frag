// Linear radiance to the display, as core's displayColor() (core/scene/image_io.cpp): scale by
// 2^exposure, tone-map, clip to [0, 1], sRGB-encode (IEC 61966-2-1).
uniform sampler2D radianceImage;
uniform float exposureScale;
uniform int toneMap;    // core's ToneMap: 0 clamp, 1 Reinhard, 2 ACES (Narkowicz's fit)
uniform ivec2 origin;  // lower-left corner of the viewport in the target
uniform vec2 viewportSize;  // the image fills it: at its own size texel for texel, else scaled

out vec4 displayColor;

vec3 toneMapped(vec3 c) {
    if (toneMap == 1) return c / (1.0 + c);
    if (toneMap == 2) return (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
    return c;
}

float linearToSrgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

// The displayed (linear) value of one texel: exposure, curve, clip.
vec3 displayed(ivec2 texel) {
    vec3 c = texelFetch(radianceImage, texel, 0).rgb * exposureScale;
    return clamp(toneMapped(max(c, vec3(0.0))), 0.0, 1.0);
}

void main() {
    vec2 p = gl_FragCoord.xy - vec2(origin);
    ivec2 size = textureSize(radianceImage, 0);
    vec3 c;
    if (size == ivec2(viewportSize)) {
        c = displayed(ivec2(p));
    } else {
        // Bilinear between the four nearest texels, each through the curve first: blending
        // radiance before the curve would brighten every edge between light and dark, and the
        // scaled-up frame would look brighter than the full one.
        vec2 t = p * vec2(size) / viewportSize - 0.5;
        ivec2 i = ivec2(floor(t)), hi = size - 1;
        vec2 f = t - floor(t);
        vec3 c00 = displayed(clamp(i, ivec2(0), hi)), c10 = displayed(clamp(i + ivec2(1, 0), ivec2(0), hi));
        vec3 c01 = displayed(clamp(i + ivec2(0, 1), ivec2(0), hi)), c11 = displayed(clamp(i + ivec2(1, 1), ivec2(0), hi));
        c = mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
    }
    displayColor = vec4(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b), 1.0);
}
