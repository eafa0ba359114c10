#pragma once
// The options of `woven render` that say what to render and how, besides the scene, the output
// and the samples: the frame options it shares with the previewer (frame_options.h) and
// --threads. `woven submit` registers the same options and passes what it was given on to every
// task's `woven render`.
#include <CLI/CLI.hpp>

#include <vector>

#include "frame_options.h"

namespace woven {

struct RenderOptions {
    FrameOptions frame;
    int threads = 0;  // 0: all cores
};

// Registers them on `command`; returns them, so that a caller can see which were given.
std::vector<CLI::Option*> addRenderOptions(CLI::App& command, RenderOptions& options);

}  // namespace woven
