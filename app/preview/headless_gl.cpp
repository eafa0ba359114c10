#include "headless_gl.h"

// epoxy's headers come first: they stand in for GL/gl.h, which osmesa.h includes.
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <GL/osmesa.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "gl_error.h"

namespace woven {

namespace {

constexpr int kMajor = 4, kMinor = 1;

std::string eglErrorName(EGLint e) {
    switch (e) {
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(e);
    }
}

class EglContext : public HeadlessGl {
public:
    EglContext(EGLDisplay display, EGLContext context, std::string platform)
        : display_(display), context_(context), platform_(std::move(platform)) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    std::string description() const override { return platform_ + ": " + currentGlDescription(); }

private:
    EGLDisplay display_;
    EGLContext context_;
    std::string platform_;
};

// A core-profile context on `display`, current without a surface; nullptr and `why` on failure.
std::unique_ptr<HeadlessGl> contextOn(EGLDisplay display, const std::string& platform, std::string& why) {
    if (display == EGL_NO_DISPLAY) { why = platform + ": no display"; return nullptr; }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        why = platform + ": eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
        return nullptr;
    }
    auto fail = [&](const std::string& what) {
        why = platform + ": " + what + " (" + eglErrorName(eglGetError()) + ")";
        eglTerminate(display);
        return nullptr;
    };
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!extensions || !std::strstr(extensions, "EGL_KHR_surfaceless_context"))
        return fail("no EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("desktop OpenGL not supported");
    // EGL_SURFACE_TYPE defaults to windows, which a surfaceless display has none of.
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count < 1)
        return fail("no OpenGL config");
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, kMajor, EGL_CONTEXT_MINOR_VERSION, kMinor,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return fail("no OpenGL 4.1 core context");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        return fail("eglMakeCurrent without a surface failed");
    }
    return std::make_unique<EglContext>(display, context, platform);
}

std::unique_ptr<HeadlessGl> createEgl(std::string& why) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!clientExtensions || !std::strstr(clientExtensions, "EGL_EXT_platform_base")) {
        why = "EGL: no EGL_EXT_platform_base";
        return nullptr;
    }
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    std::string reasons;
    auto note = [&](const std::string& r) { reasons += (reasons.empty() ? "" : "; ") + r; };
    if (std::strstr(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (auto c = contextOn(d, "EGL surfaceless", why)) return c;
        note(why);
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (queryDevices && std::strstr(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        queryDevices(16, devices, &count);
        for (EGLint i = 0; i < count; ++i) {
            EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            if (auto c = contextOn(d, "EGL device " + std::to_string(i), why)) return c;
            note(why);
        }
    }
    why = reasons.empty() ? "EGL: neither the surfaceless nor the device platform is available" : reasons;
    return nullptr;
}

class OsMesaContext : public HeadlessGl {
public:
    OsMesaContext(OSMesaContext context) : context_(context), pixels_(4) {
        // OSMesa needs a colour buffer to make current; drawing goes to framebuffer objects.
        OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, 1, 1);
    }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }
    std::string description() const override { return "OSMesa: " + currentGlDescription(); }

private:
    OSMesaContext context_;
    std::vector<unsigned char> pixels_;
};

std::unique_ptr<HeadlessGl> createOsMesa(std::string& why) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, kMajor, OSMESA_CONTEXT_MINOR_VERSION, kMinor, 0};
    OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context) {
        why = "OSMesa: no OpenGL 4.1 core context";
        return nullptr;
    }
    auto c = std::make_unique<OsMesaContext>(context);
    // libepoxy resolves GL calls through libGL (libglvnd), which does not dispatch to OSMesa's
    // context on glvnd systems: then the context exists but is unreachable.
    if (!glGetString(GL_VERSION)) {
        why = "OSMesa: context made, but OpenGL calls through libepoxy do not reach it";
        return nullptr;
    }
    return c;
}

}  // namespace

std::string currentGlDescription() {
    auto str = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

std::unique_ptr<HeadlessGl> HeadlessGl::create() {
    const char* only = std::getenv("WOVEN_GL");
    const std::string choice = only ? only : "";
    if (!choice.empty() && choice != "egl" && choice != "osmesa")
        throw GlError("WOVEN_GL='" + choice + "': use 'egl' or 'osmesa'");
    std::string reasons, why;
    if (choice != "osmesa") {
        if (auto c = createEgl(why)) return c;
        reasons += why;
    }
    if (choice != "egl") {
        if (auto c = createOsMesa(why)) return c;
        reasons += (reasons.empty() ? "" : "; ") + why;
    }
    throw GlError("no headless OpenGL 4.1 core context could be made: " + reasons);
}

}  // namespace woven
