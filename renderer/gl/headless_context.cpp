// EGL context creation: surfaceless Mesa platform first, the default display as a fallback.
#include "gl/headless_context.h"

#include <epoxy/egl.h>

namespace gbl {

namespace {
EGLDisplay openDisplay() {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
    return EGL_NO_DISPLAY;
}
}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error, bool debug) {
    auto fail = [&](std::string msg) -> std::unique_ptr<HeadlessContext> {
        if (error) *error = std::move(msg);
        return nullptr;
    };
    EGLDisplay display = openDisplay();
    if (display == EGL_NO_DISPLAY)
        return fail("no EGL display could be opened for a headless OpenGL context (is Mesa's libegl installed?)");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("this EGL implementation does not offer desktop OpenGL");

    EGLint const configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                    EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0) {
        // Surfaceless displays may expose configs without pbuffer support.
        EGLint const anyConfig[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        if (!eglChooseConfig(display, anyConfig, &config, 1, &count) || count == 0)
            return fail("no EGL config supports desktop OpenGL");
    }

    static constexpr int kVersions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
    EGLContext context = EGL_NO_CONTEXT;
    for (auto const& v : kVersions) {
        EGLint const attribs[] = {EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION, v[1],
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
        if (context != EGL_NO_CONTEXT) break;
    }
    if (context == EGL_NO_CONTEXT) return fail("no OpenGL 3.3 core context could be created through EGL");

    std::unique_ptr<HeadlessContext> ctx(new HeadlessContext());
    ctx->display_ = display;
    ctx->context_ = context;
    if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
        EGLint const pbufferAttribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        ctx->surface_ = eglCreatePbufferSurface(display, config, pbufferAttribs);
    }
    ctx->makeCurrent();
    if (eglGetCurrentContext() != context) return fail("the headless OpenGL context could not be made current");
    return ctx;
}

void HeadlessContext::makeCurrent() {
    EGLSurface s = surface_ ? EGLSurface(surface_) : EGL_NO_SURFACE;
    eglMakeCurrent(EGLDisplay(display_), s, s, EGLContext(context_));
}

HeadlessContext::~HeadlessContext() {
    EGLDisplay d = EGLDisplay(display_);
    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_) eglDestroySurface(d, EGLSurface(surface_));
    eglDestroyContext(d, EGLContext(context_));
    eglTerminate(d);
}

}  // namespace gbl
