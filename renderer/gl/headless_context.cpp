// Chooses the headless context's backend: EGL when built with it, else (or when asked) a hidden GLFW window.
#include "gl/headless_context.h"

#include "gl/headless_backend.h"

#include <cstdio>
#include <cstdlib>

namespace gbl {

HeadlessContext::HeadlessContext(std::unique_ptr<detail::HeadlessBackend> impl, Backend backend)
    : impl_(std::move(impl)), backend_(backend) {}

HeadlessContext::~HeadlessContext() = default;

void HeadlessContext::makeCurrent() {
    impl_->makeCurrent();
}

bool HeadlessContext::hasEgl() {
#ifdef GBL_HEADLESS_GLFW
    return false;
#else
    return true;
#endif
}

char const* backendName(HeadlessContext::Backend backend) {
    return backend == HeadlessContext::Backend::Egl ? "egl" : "glfw";
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(std::string* error, bool debug) {
    auto fail = [&](std::string msg) -> std::unique_ptr<HeadlessContext> {
        if (error) *error = std::move(msg);
        return nullptr;
    };
    char const* env = std::getenv("GBL_HEADLESS");
    std::string const asked = env ? env : "";
    if (!asked.empty() && asked != "egl" && asked != "glfw")
        return fail("GBL_HEADLESS=" + asked + " names no headless OpenGL backend (use egl or glfw, or unset it)");
    if (asked == "egl" && !hasEgl())
        return fail(
            "GBL_HEADLESS=egl, but this build has no EGL (configured without libEGL or with "
            "-DGBL_HEADLESS_GLFW=ON)");

    std::string eglReason;
#ifndef GBL_HEADLESS_GLFW
    if (asked != "glfw") {
        if (auto egl = detail::createEglContext(debug, &eglReason))
            return std::unique_ptr<HeadlessContext>(new HeadlessContext(std::move(egl), Backend::Egl));
        if (asked == "egl") return fail("no OpenGL context: EGL failed (" + eglReason + ")");
    }
#endif
    std::string glfwReason;
    if (auto glfw = detail::createGlfwContext(debug, &glfwReason)) {
        // A fallback is said once, so a machine whose EGL broke does not pass for one that works.
        if (!eglReason.empty())
            std::fprintf(stderr, "EGL failed (%s); using a hidden GLFW window\n", eglReason.c_str());
        return std::unique_ptr<HeadlessContext>(new HeadlessContext(std::move(glfw), Backend::Glfw));
    }
    if (!eglReason.empty()) return fail("no OpenGL context: EGL failed (" + eglReason + ") and " + glfwReason);
    return fail("no OpenGL context: " + glfwReason);
}

}  // namespace gbl
