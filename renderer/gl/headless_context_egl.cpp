// EGL headless context: surfaceless Mesa platform first, the default display as a fallback.
#include "gl/headless_backend.h"

#include <epoxy/egl.h>

namespace gbl::detail {

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

class EglContext final : public HeadlessBackend {
public:
    explicit EglContext(EGLDisplay display) : display_(display) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    EglContext(EglContext const&) = delete;
    EglContext& operator=(EglContext const&) = delete;

    void makeCurrent() override { eglMakeCurrent(display_, surface_, surface_, context_); }

    EGLDisplay display_;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;  // a 1x1 pbuffer when surfaceless contexts are unsupported
};
}  // namespace

std::unique_ptr<HeadlessBackend> createEglContext(bool debug, std::string* reason) {
    auto fail = [&](char const* msg) -> std::unique_ptr<HeadlessBackend> {
        *reason = msg;
        return nullptr;
    };
    EGLDisplay display = openDisplay();
    if (display == EGL_NO_DISPLAY) return fail("no EGL display could be opened; is Mesa's libegl installed?");
    auto ctx = std::make_unique<EglContext>(display);  // terminates the display on every return below
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("this EGL implementation does not offer desktop OpenGL");

    // EGL attribute lists are key, value pairs: one pair a line (clang-format would put one item a line).
    // clang-format off
    EGLint const configAttribs[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
        EGL_NONE};
    // clang-format on
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0) {
        // Surfaceless displays may expose configs without pbuffer support.
        EGLint const anyConfig[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        if (!eglChooseConfig(display, anyConfig, &config, 1, &count) || count == 0)
            return fail("no EGL config supports desktop OpenGL");
    }

    for (auto const& v : kContextVersions) {
        // clang-format off
        EGLint const attribs[] = {
            EGL_CONTEXT_MAJOR_VERSION, v[0],
            EGL_CONTEXT_MINOR_VERSION, v[1],
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
            EGL_NONE};
        // clang-format on
        ctx->context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
        if (ctx->context_ != EGL_NO_CONTEXT) break;
    }
    if (ctx->context_ == EGL_NO_CONTEXT) return fail("no OpenGL 3.3 core context could be created through EGL");

    if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
        EGLint const pbufferAttribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        ctx->surface_ = eglCreatePbufferSurface(display, config, pbufferAttribs);
    }
    ctx->makeCurrent();
    if (eglGetCurrentContext() != ctx->context_) return fail("the EGL context could not be made current");
    return ctx;
}

}  // namespace gbl::detail
