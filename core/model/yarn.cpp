#include "yarn.h"

namespace woven {

Yarn sideYarn(const WovenParams& p, YarnSide side) {
    Yarn yarn;
    for (const ParamInfo& info : wovenParamTable())
        if (info.yarnField >= 0 && (info.yarnSide == side || info.yarnSide == YarnSide::Both))
            yarn.value[size_t(info.yarnField)] = *reinterpret_cast<const float*>(reinterpret_cast<const char*>(&p) + info.offset);
    return yarn;
}

Yarn resolve(const YarnSpec& type, const Yarn& sideDefault) {
    Yarn yarn = sideDefault;
    for (int f = 0; f < kYarnFieldCount; ++f)
        if (type.set[size_t(f)]) yarn.value[size_t(f)] = type.value[size_t(f)];
    return yarn;
}

}  // namespace woven
