#pragma once
// What makes a render a part of one frame rather than of another, besides its size and its
// sample range (sample_range.h): a frame is a pure function of (scene, seed, sample range) for
// one integrator and the options that change what a sample is. Part files record it, and `woven
// merge` refuses parts whose identities differ. What only decides how many samples a pixel takes
// (--spp, --time, --noise-threshold, which `woven submit` gives each task its own share of) or
// how a PNG shows them (--exposure, --tone-map) is no part of it.
#include <cstdint>
#include <string>

namespace woven {

struct FrameIdentity {
    std::string scene;       // sceneHash() of the scene as rendered, through the camera it used
    uint64_t seed = 0;
    // integratorRecord() (integrators.h): an integrator's name, prefixed by auto's where its
    // pilot chose (it times each, so the tasks of one frame may choose differently), or auto's
    // alone for a merge of frames it chose differently for.
    std::string integrator;
    int maxDepth = 0;
    bool filterWeave = false;
    // samplerName() of the sampler its numbers came from: the same sample index is another
    // sample under each. Empty in frames written before woven recorded it.
    std::string sampler;
};

}  // namespace woven
