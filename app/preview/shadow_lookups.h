#pragma once
// Which shadow-map lookups a surface program compiles in (shaders/lighting.glsl): none, the
// opaque occluders' (PREVIEW_SHADOWS), or also the light that occluders letting it through pass
// (PREVIEW_TRANSMITTED_SHADOWS), which only a scene with such an occluder pays for.
#include <string>

namespace woven {

enum class ShadowLookups { None, Opaque, Transmitted };

inline std::string shadowLookupDefines(ShadowLookups lookups) {
    switch (lookups) {
        case ShadowLookups::None: break;
        case ShadowLookups::Opaque: return "#define PREVIEW_SHADOWS\n";
        case ShadowLookups::Transmitted: return "#define PREVIEW_SHADOWS\n#define PREVIEW_TRANSMITTED_SHADOWS\n";
    }
    return "";
}

}  // namespace woven
