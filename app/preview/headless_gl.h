#pragma once
// An OpenGL 4.1+ core context without a window, for screenshots, tests and benchmarks. It tries
// Mesa's surfaceless EGL platform (llvmpipe where there is no GPU), then an EGL device (GPU
// drivers that lack the Mesa platform), then OSMesa. All drawing goes to framebuffer objects,
// so the rest of the previewer does not know which one it got.
#include <memory>
#include <string>

namespace woven {

class HeadlessGl {
public:
    // Makes the context current on this thread. WOVEN_GL=egl or WOVEN_GL=osmesa restricts the
    // choice to one backend. Throws GlError naming every backend tried and why it failed.
    static std::unique_ptr<HeadlessGl> create();
    virtual ~HeadlessGl() = default;

    // "EGL surfaceless: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
    virtual std::string description() const = 0;
};

// Renderer and version of the current context, for messages and benchmarks.
std::string currentGlDescription();

}  // namespace woven
