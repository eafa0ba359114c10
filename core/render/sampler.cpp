#include "sampler.h"

#include <iterator>
#include <stdexcept>

namespace woven {

SamplerKind samplerKind(const std::string& name) {
    for (size_t i = 0; i < std::size(kSamplerNames); ++i)
        if (name == kSamplerNames[i]) return SamplerKind(i);
    throw std::invalid_argument("unknown sampler '" + name + "' (expected sobol or independent)");
}

}  // namespace woven
