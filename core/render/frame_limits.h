#pragma once
// What a frame may ask of the machine that renders it, checked before anything is allocated:
// the command line allows frames of 32768 x 32768, whose film alone would take hundreds of
// gigabytes, and any thread count.
#include <cstddef>

#include "system_memory.h"

namespace woven {

// What a frame holds per pixel while it renders and is written, rounded up: the film's exact
// sums and count with its render passes' sums (260 bytes), a pass with its first hits and
// combined estimates (64), the snapshot and the frame file's copy of it (2 x 272) with the
// passes' means (40), and the EXR's 95 channels, a float each, as written (380), plus
// room for per-pixel statistics and the denoiser's buffers.
constexpr size_t kFrameBytesPerPixel = 2048;

// Throws std::invalid_argument naming the size, the estimate and the memory when a width x
// height frame's estimate exceeds this machine's physical memory.
void checkFrameFitsInMemory(int width, int height);

// The worker threads for RenderSettings::threads: 0, and anything above the hardware threads
// this process may use, give all of those (more would only oversubscribe the cores, and TBB
// fails at exit with tens of thousands).
int workerThreads(int requested);

}  // namespace woven
