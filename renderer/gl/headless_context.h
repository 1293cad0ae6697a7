// An OpenGL context without a visible window (EGL, or a hidden GLFW window), for tests and render/bench.
#pragma once

#include <memory>
#include <string>

namespace gbl {

namespace detail {
class HeadlessBackend;
}

class HeadlessContext {
public:
    enum class Backend { Egl, Glfw };

    // Creates and makes current a core-profile context, trying 4.6 down to 3.3. EGL is used when the build
    // has it, with a hidden GLFW window (which needs a display) as the fallback; GBL_HEADLESS=egl or
    // GBL_HEADLESS=glfw in the environment asks for one backend and allows no fallback. Returns null and
    // sets *error to one sentence when no context can be had.
    static std::unique_ptr<HeadlessContext> create(std::string* error, bool debug = true);
    // False where the build has no EGL: macOS, Windows, or Linux configured with -DGBL_HEADLESS_GLFW=ON.
    static bool hasEgl();

    ~HeadlessContext();
    HeadlessContext(HeadlessContext const&) = delete;
    HeadlessContext& operator=(HeadlessContext const&) = delete;

    void makeCurrent();
    Backend backend() const { return backend_; }

private:
    HeadlessContext(std::unique_ptr<detail::HeadlessBackend> impl, Backend backend);
    std::unique_ptr<detail::HeadlessBackend> impl_;
    Backend backend_;
};

// "egl" or "glfw", the names GBL_HEADLESS takes.
char const* backendName(HeadlessContext::Backend backend);

}  // namespace gbl
