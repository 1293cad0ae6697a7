// Hidden GLFW window as the headless context, where EGL is missing (macOS, Windows) or not wanted.
#include "gl/headless_backend.h"

#define GLFW_INCLUDE_NONE  // epoxy provides the GL declarations
#include <GLFW/glfw3.h>

namespace gbl::detail {

namespace {
std::string takeGlfwError() {
    char const* description = nullptr;
    glfwGetError(&description);
    return description ? description : "GLFW gave no reason";
}

class GlfwContext final : public HeadlessBackend {
public:
    explicit GlfwContext(GLFWwindow* window) : window_(window) {}
    // The context owns GLFW's initialisation: the render/bench commands and tests open no other window.
    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    GlfwContext(GlfwContext const&) = delete;
    GlfwContext& operator=(GlfwContext const&) = delete;

    void makeCurrent() override { glfwMakeContextCurrent(window_); }

private:
    GLFWwindow* window_;
};
}  // namespace

std::unique_ptr<HeadlessBackend> createGlfwContext(bool debug, std::string* reason) {
    glfwGetError(nullptr);  // an earlier, unrelated error must not be reported as this one's reason
    if (!glfwInit()) {
        *reason = "no display for a hidden GLFW window (" + takeGlfwError() + "; set DISPLAY or run under xvfb-run)";
        return nullptr;
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);  // macOS offers 3.2+ core contexts only this way
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    GLFWwindow* window = nullptr;
    std::string lastError;
    for (auto const& v : kContextVersions) {
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
        // Rendering goes to framebuffer objects; the window's own 1x1 framebuffer is never drawn to.
        window = glfwCreateWindow(1, 1, "gbuffer-lab headless", nullptr, nullptr);
        if (window) break;
        lastError = takeGlfwError();
    }
    if (!window) {
        *reason = "a hidden GLFW window gave no OpenGL 3.3 core context (" + lastError + ")";
        glfwTerminate();
        return nullptr;
    }
    auto ctx = std::make_unique<GlfwContext>(window);
    ctx->makeCurrent();
    if (glfwGetCurrentContext() != window) {
        *reason = "the hidden GLFW window's context could not be made current (" + takeGlfwError() + ")";
        return nullptr;
    }
    return ctx;
}

}  // namespace gbl::detail
