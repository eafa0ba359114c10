#pragma once
// The sRGB transfer functions (IEC 61966-2-1), on one channel: colours in image files and
// weaving drafts are sRGB-encoded, woven computes in linear RGB.

namespace woven {

float srgbToLinear(float encoded);
float linearToSrgb(float linear);

}  // namespace woven
